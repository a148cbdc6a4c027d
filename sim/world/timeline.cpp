#include "sim/world/timeline.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace forcelab::sim {

namespace {
// bytes a map node adds to what it holds (three pointers, a colour, padding)
constexpr std::size_t kNodeBytes = 48;
} // namespace

std::size_t Timeline::worldBytes(int balls)
{
    return kWorldFixedBytes + kWorldBytesPerBall * static_cast<std::size_t>(std::max(0, balls));
}

// Of the budget, 1/64 is left for the logged inputs (a pointer move costs
// about 100 bytes: 2.6 MB of 256 MiB is 7 hours of moves at 60 a second).
// Of the checkpoints that fit, the reserve is kept for edits and one more
// marks the start of the span, so `regular` intervals of K steps are always
// held: K is the smallest interval with regular × K ≥ the steps to cover.
Timeline::Plan Timeline::plan(int balls, double dt, std::size_t budget, double coverSeconds)
{
    Plan p;
    p.worldBytes = worldBytes(balls);
    p.maxCheckpoints = static_cast<int>(std::max<std::size_t>(1, (budget - budget / 64) / p.worldBytes));
    const int reserve = std::min(kForcedReserve, (p.maxCheckpoints - 1) / 2);
    const int regular = std::max(1, p.maxCheckpoints - reserve - 1);
    const double steps = dt > 0.0 ? std::ceil(coverSeconds / dt) : 1.0;
    p.interval = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(steps / regular)));
    p.coveredSteps = p.interval * regular;
    p.coveredSeconds = static_cast<double>(p.coveredSteps) * dt;
    return p;
}

Timeline::Timeline(std::size_t budget, double coverSeconds)
    : m_budget(budget)
    , m_coverSeconds(coverSeconds)
{
}

void Timeline::start(const World& world)
{
    m_checkpoints.clear();
    m_inputs.clear();
    m_cuts.clear();
    m_lastCut = -1;
    m_checkpoints.emplace(world.stepCount(), world);
    m_latest = world.stepCount();
    m_latestTime = world.time();
    m_lastCheckpoint = m_latest;
    m_bytes = worldBytes(world.balls().size());
    setCursor(world);
}

std::int64_t Timeline::earliestStep() const
{
    return m_checkpoints.empty() ? 0 : m_checkpoints.begin()->first;
}

double Timeline::earliestTime() const
{
    return m_checkpoints.empty() ? 0.0 : m_checkpoints.begin()->second.time();
}

bool Timeline::hasCut(int id) const
{
    return std::any_of(m_cuts.begin(), m_cuts.end(), [id](const Cut& c) { return c.id == id; });
}

void Timeline::setCursor(const World& world)
{
    m_cursorValid = true;
    m_cursorStep = world.stepCount();
    m_cursorPointerChanges = world.pointerChanges();
}

bool Timeline::onCursor(const World& world) const
{
    return m_cursorValid && world.stepCount() == m_cursorStep && world.pointerChanges() == m_cursorPointerChanges &&
           m_cursorStep >= earliestStep() && m_cursorStep <= m_latest;
}

std::size_t Timeline::inputBytes(const Input& input)
{
    std::size_t bytes = kNodeBytes + sizeof(std::pair<const std::int64_t, Input>);
    if (input.settings) {
        const CustomForceSettings& c = input.settings->custom;
        bytes += sizeof(WorldSettings) + c.fx.capacity() + c.fy.capacity() + c.potential.capacity() +
                 c.constants.capacity() * (sizeof(CustomConstant) + 16);
    }
    return bytes;
}

void Timeline::countInput(const Input& input, int sign)
{
    if (sign > 0)
        m_bytes += inputBytes(input);
    else
        m_bytes -= std::min(m_bytes, inputBytes(input));
}

void Timeline::apply(const Input& input, World& world)
{
    if (input.pointer) {
        // A change, even back to where it was, makes the integrator start
        // afresh: going through another value does the same here.
        PointerInput other = *input.pointer;
        other.inside = !other.inside;
        world.setPointer(other);
        world.setPointer(*input.pointer);
    }
    if (input.settings)
        (void)world.setSettings(*input.settings); // accepted when it was pushed
}

void Timeline::applyInputsAt(std::int64_t step, World& world) const
{
    if (const auto it = m_inputs.find(step); it != m_inputs.end())
        apply(it->second, world);
}

// `world` is on the record (its step's inputs applied); steps it to `to`.
bool Timeline::replayFrom(World& world, std::int64_t to)
{
    while (world.stepCount() < to) {
        const std::int64_t k = world.stepCount();
        world.step();
        if (world.stepCount() != k + 1)
            break; // it halted where the record went on: the record is not this world's
        applyInputsAt(k + 1, world);
    }
    setCursor(world);
    return world.stepCount() == to;
}

bool Timeline::seek(std::int64_t step, World& world)
{
    if (m_checkpoints.empty() || step < earliestStep() || step > m_latest)
        return false;
    const auto c = std::prev(m_checkpoints.upper_bound(step));
    const bool fromHere = onCursor(world) && m_cursorStep <= step && m_cursorStep >= c->first;
    if (!fromHere) {
        world = c->second;
        applyInputsAt(c->first, world);
    }
    return replayFrom(world, step);
}

bool Timeline::stepBack(World& world)
{
    return seek(world.stepCount() - 1, world);
}

bool Timeline::replayStep(World& world)
{
    if (world.stepCount() >= m_latest)
        return false;
    return seek(world.stepCount() + 1, world);
}

// The recorded world at `step` as it reached it, before that step's inputs.
std::unique_ptr<World> Timeline::recordedBeforeInputs(std::int64_t step)
{
    const auto c = std::prev(m_checkpoints.upper_bound(step));
    auto world = std::make_unique<World>(c->second);
    for (std::int64_t k = c->first; k < step; ++k) {
        applyInputsAt(k, *world);
        world->step();
    }
    return world;
}

void Timeline::addCheckpoint(const World& world)
{
    const std::int64_t step = world.stepCount();
    if (const auto it = m_checkpoints.find(step); it != m_checkpoints.end()) {
        m_bytes -= std::min(m_bytes, worldBytes(it->second.balls().size()));
        it->second = world;
    } else {
        m_checkpoints.emplace(step, world);
    }
    m_bytes += worldBytes(world.balls().size());
    m_lastCheckpoint = step;
}

int Timeline::cutAfter(std::int64_t step, std::unique_ptr<World> base)
{
    if (step >= m_latest)
        return -1;
    Cut cut;
    cut.id = m_nextCut++;
    cut.step = step;
    cut.latest = m_latest;
    cut.latestTime = m_latestTime;
    cut.bytes = worldBytes(base->balls().size());
    for (auto it = m_checkpoints.upper_bound(step); it != m_checkpoints.end();) {
        const std::size_t b = worldBytes(it->second.balls().size());
        m_bytes -= std::min(m_bytes, b);
        cut.bytes += b;
        auto node = m_checkpoints.extract(it++);
        cut.checkpoints.insert(std::move(node));
    }
    for (auto it = m_inputs.lower_bound(step); it != m_inputs.end();) {
        countInput(it->second, -1);
        cut.bytes += inputBytes(it->second);
        auto node = m_inputs.extract(it++);
        cut.inputs.insert(std::move(node));
    }
    m_latestTime = base->time();
    cut.base = std::move(base);
    m_bytes += cut.bytes;
    m_latest = step;
    m_lastCheckpoint = std::prev(m_checkpoints.upper_bound(step))->first;
    m_cuts.push_back(std::move(cut));
    return m_cuts.back().id;
}

void Timeline::afterStep(const World& after)
{
    const std::int64_t s = after.stepCount();
    if (m_checkpoints.empty() || s < earliestStep() || s > m_latest + 1) {
        start(after); // a world the record does not lead to
        return;
    }
    if (m_cursorValid && s == m_cursorStep) {
        edited(after); // the step did not advance: it halted and took itself back
        return;
    }
    const std::int64_t k = s - 1;
    const bool pointerMoved = after.pointerChanges() != m_cursorPointerChanges;
    if (k < m_latest) {
        if (!pointerMoved) {
            // The same inputs as recorded: the same step. The record goes on
            // to the next inputs the owner was not given.
            if (m_inputs.count(s) != 0)
                m_lastCut = cutAfter(s, std::make_unique<World>(after));
            setCursor(after);
            trim();
            return;
        }
        // Another pointer than the record's: this step ends that history.
        Input kept;
        if (const auto it = m_inputs.find(k); it != m_inputs.end())
            kept = it->second;
        m_lastCut = cutAfter(k, recordedBeforeInputs(k));
        countInput(kept, +1);
        m_inputs[k] = kept;
    }
    if (pointerMoved) {
        Input& input = m_inputs[k];
        countInput(input, -1);
        input.pointer = after.pointer();
        countInput(input, +1);
    }
    m_latest = s;
    m_latestTime = after.time();
    const Plan p = plan(after.balls().size(), after.settings().time.dt, m_budget, m_coverSeconds);
    if (s - m_lastCheckpoint >= p.interval)
        addCheckpoint(after);
    setCursor(after);
    trim();
}

void Timeline::settingsEdited(const World& now)
{
    const std::int64_t s = now.stepCount();
    if (m_checkpoints.empty() || s < earliestStep() || s > m_latest) {
        start(now);
        return;
    }
    Input input;
    if (const auto it = m_inputs.find(s); it != m_inputs.end())
        input = it->second; // already applied to now
    m_lastCut = s < m_latest ? cutAfter(s, recordedBeforeInputs(s)) : -1;
    if (const auto it = m_inputs.find(s); it != m_inputs.end()) {
        countInput(it->second, -1);
        m_inputs.erase(it);
    }
    if (now.pointerChanges() != m_cursorPointerChanges)
        input.pointer = now.pointer();
    input.settings = std::make_shared<const WorldSettings>(now.settings());
    countInput(input, +1);
    m_inputs[s] = std::move(input);
    setCursor(now);
    trim();
}

void Timeline::edited(const World& now)
{
    const std::int64_t s = now.stepCount();
    if (m_checkpoints.empty() || s < earliestStep() || s > m_latest) {
        start(now);
        return;
    }
    m_lastCut = s < m_latest ? cutAfter(s, recordedBeforeInputs(s)) : -1;
    if (const auto it = m_inputs.find(s); it != m_inputs.end()) {
        countInput(it->second, -1);
        m_inputs.erase(it); // now has them
    }
    addCheckpoint(now);
    m_latestTime = now.time();
    setCursor(now);
    trim();
}

bool Timeline::restoreCut(int id, World& world)
{
    const auto found = std::find_if(m_cuts.begin(), m_cuts.end(), [id](const Cut& c) { return c.id == id; });
    if (found == m_cuts.end() || found->step < earliestStep() || found->step > m_latest)
        return false;
    Cut cut = std::move(*found);
    m_cuts.erase(found);
    m_bytes -= std::min(m_bytes, cut.bytes);
    const std::int64_t s = cut.step;
    // What was recorded after the edit becomes a cut of its own (a redo).
    m_lastCut = cutAfter(s, recordedBeforeInputs(s));
    if (const auto it = m_inputs.find(s); it != m_inputs.end()) {
        countInput(it->second, -1);
        m_inputs.erase(it);
    }
    if (const auto it = m_checkpoints.find(s); it != m_checkpoints.end()) {
        m_bytes -= std::min(m_bytes, worldBytes(it->second.balls().size()));
        m_checkpoints.erase(it);
    }
    m_checkpoints.emplace(s, std::move(*cut.base));
    m_bytes += worldBytes(m_checkpoints.at(s).balls().size());
    for (auto& [step, w] : cut.checkpoints) {
        m_bytes += worldBytes(w.balls().size());
        m_checkpoints.emplace(step, std::move(w));
    }
    for (auto& [step, input] : cut.inputs) {
        countInput(input, +1);
        m_inputs.emplace(step, std::move(input));
    }
    m_latest = cut.latest;
    m_latestTime = cut.latestTime;
    m_lastCheckpoint = m_checkpoints.rbegin()->first;
    world = m_checkpoints.at(s);
    applyInputsAt(s, world);
    setCursor(world);
    trim();
    return true;
}

// Over the budget: the oldest cut goes first, then the oldest checkpoint with
// the inputs before the next one (the earliest step moves up to it).
void Timeline::trim()
{
    while (m_bytes > m_budget) {
        if (!m_cuts.empty()) {
            if (m_cuts.front().id == m_lastCut)
                m_lastCut = -1;
            m_bytes -= std::min(m_bytes, m_cuts.front().bytes);
            m_cuts.erase(m_cuts.begin());
            continue;
        }
        if (m_checkpoints.size() < 2)
            return;
        const auto first = m_checkpoints.begin();
        m_bytes -= std::min(m_bytes, worldBytes(first->second.balls().size()));
        m_checkpoints.erase(first);
        const std::int64_t earliest = m_checkpoints.begin()->first;
        for (auto it = m_inputs.begin(); it != m_inputs.end() && it->first < earliest;) {
            countInput(it->second, -1);
            it = m_inputs.erase(it);
        }
    }
}

} // namespace forcelab::sim

#include "ui/docks/predict_dock.h"

#include "lessons/lesson_markup.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/drawing/display_units.h"

#include "sim/studies/claims.h"

#include <QButtonGroup>
#include <QDoubleValidator>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace forcelab {

namespace {

QString qs(std::string_view s)
{
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QString number(double v)
{
    return QString::number(v, 'g', std::abs(v) >= 1e5 ? 4 : 5);
}

} // namespace

PredictDock::PredictDock(SimulationController* controller, QWidget* parent)
    : QDockWidget(tr("Predict"), parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("predictDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    m_ask = new QLabel(body);
    m_ask->setObjectName(QStringLiteral("predictQuestion"));
    m_ask->setWordWrap(true);
    m_ask->setTextFormat(Qt::PlainText); // a lesson's words never load what an <img> names
    QFont big = m_ask->font();
    big.setPointSizeF(big.pointSizeF() * 1.2);
    big.setBold(true);
    m_ask->setFont(big);
    layout->addWidget(m_ask);

    auto* row = new QHBoxLayout;
    m_number = new QLineEdit(body);
    m_number->setObjectName(QStringLiteral("predictNumber"));
    m_number->setAccessibleName(tr("Your prediction"));
    m_number->setPlaceholderText(tr("your guess"));
    auto* validator = new QDoubleValidator(m_number);
    validator->setNotation(QDoubleValidator::StandardNotation);
    validator->setLocale(QLocale()); // the language's (1,5 in German; language.h)
    m_number->setValidator(validator);
    m_unit = new QLabel(body);
    m_unit->setObjectName(QStringLiteral("predictUnit"));
    row->addWidget(m_number, 1);
    row->addWidget(m_unit);
    layout->addLayout(row);

    m_choiceBox = new QWidget(body);
    m_choiceLayout = new QVBoxLayout(m_choiceBox);
    m_choiceLayout->setContentsMargins(0, 0, 0, 0);
    m_choices = new QButtonGroup(this);
    layout->addWidget(m_choiceBox);

    auto* buttons = new QHBoxLayout;
    m_run = new QPushButton(tr("Lock in and run"), body);
    m_run->setObjectName(QStringLiteral("predictRun"));
    m_show = new QPushButton(tr("Show the answer now"), body);
    m_show->setObjectName(QStringLiteral("predictShow"));
    m_next = new QPushButton(tr("Next question"), body);
    m_next->setObjectName(QStringLiteral("predictNext"));
    buttons->addWidget(m_run);
    buttons->addWidget(m_show);
    buttons->addWidget(m_next);
    layout->addLayout(buttons);

    // While the answer is measured: how far, and a way out.
    auto* measuringRow = new QHBoxLayout;
    m_progress = new QProgressBar(body);
    m_progress->setObjectName(QStringLiteral("predictProgress"));
    m_progress->setRange(0, 100);
    m_cancel = new QPushButton(tr("Cancel"), body);
    m_cancel->setObjectName(QStringLiteral("predictCancel"));
    measuringRow->addWidget(m_progress, 1);
    measuringRow->addWidget(m_cancel);
    layout->addLayout(measuringRow);
    m_progress->hide();
    m_cancel->hide();

    m_result = new QLabel(body);
    m_result->setObjectName(QStringLiteral("predictResult"));
    m_result->setWordWrap(true);
    m_result->setTextFormat(Qt::RichText);
    layout->addWidget(m_result);
    layout->addStretch(1);
    setWidget(body);

    connect(m_run, &QPushButton::clicked, this, &PredictDock::lockIn);
    connect(m_number, &QLineEdit::returnPressed, this, &PredictDock::lockIn);
    connect(m_show, &QPushButton::clicked, this, &PredictDock::reveal);
    connect(m_cancel, &QPushButton::clicked, this, &PredictDock::cancelMeasurement);
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &PredictDock::measurementFinished);
    connect(m_next, &QPushButton::clicked, this, &PredictDock::nextQuestion);
    connect(m_controller, &SimulationController::stepped, this, &PredictDock::onStepped);
    // A reset or a new scene asks again.
    connect(m_controller, &SimulationController::sceneChanged, this, &PredictDock::showQuestion);
    showQuestion();
}

PredictDock::~PredictDock()
{
    // The worker reads its own copy of the scene but polls our flag.
    m_cancelFlag = true;
    m_watcher.waitForFinished();
}

void PredictDock::setLesson(const Lesson& lesson)
{
    m_lesson = lesson;
    m_question = 0;
    showQuestion();
}

// The claim's unit as the student reads it (m/s in SI mode, px/s in
// pixels); the answers are kept in the claim's own units and converted
// only to be shown or read.
ShownUnit PredictDock::unitOf(const sim::Claim& claim) const
{
    const sim::ClaimMeasure* m = sim::findClaimMeasure(claim.measure);
    if (!m || m->unit == "1")
        return {};
    return shownUnit(qs(m->unit), displayUnits());
}

void PredictDock::showQuestion()
{
    if (m_watcher.isRunning()) { // a new question or a reset: the running measurement is not wanted
        m_cancelFlag = true;
        m_discard = true;
    }
    m_progress->hide();
    m_cancel->hide();
    m_predicted.reset();
    m_measured.reset();
    m_revealed = false;
    m_result->clear();
    const bool any = !m_lesson.predict.empty();
    if (!any) {
        m_ask->setText(tr("This lesson asks no question before it runs."));
        m_number->hide();
        m_unit->hide();
        m_choiceBox->hide();
        m_run->hide();
        m_show->hide();
        m_next->hide();
        return;
    }
    m_question = std::clamp(m_question, 0, static_cast<int>(m_lesson.predict.size()) - 1);
    const Prediction& q = m_lesson.predict[static_cast<std::size_t>(m_question)];
    const sim::Claim& claim = m_lesson.claims[static_cast<std::size_t>(q.claim)];
    m_ask->setText(lessons::markupToPlainText(q.ask));
    const bool choices = !q.choices.isEmpty();
    m_number->setVisible(!choices);
    m_unit->setVisible(!choices);
    m_number->clear();
    m_number->setEnabled(true);
    m_unit->setText(unitOf(claim).text);
    for (QAbstractButton* b : m_choices->buttons()) {
        m_choices->removeButton(b);
        delete b;
    }
    for (qsizetype k = 0; k < q.choices.size(); ++k) {
        auto* b = new QRadioButton(lessons::markupToPlainText(q.choices[k]), m_choiceBox);
        b->setObjectName(QStringLiteral("predictChoice%1").arg(k));
        m_choices->addButton(b, static_cast<int>(k));
        m_choiceLayout->addWidget(b);
    }
    m_choiceBox->setVisible(choices);
    m_run->show();
    m_run->setEnabled(true);
    m_show->show();
    m_show->setEnabled(false);
    m_next->setVisible(m_lesson.predict.size() > 1);
    m_result->setText(tr("Make your prediction while the lesson waits at t = 0, then run it."));
}

void PredictDock::lockIn()
{
    if (m_lesson.predict.empty() || m_predicted)
        return;
    const Prediction& q = m_lesson.predict[static_cast<std::size_t>(m_question)];
    if (q.choices.isEmpty()) {
        bool ok = false;
        const double value = QLocale().toDouble(m_number->text().trimmed(), &ok);
        if (!ok || !std::isfinite(value)) {
            m_result->setText(tr("Type a number first (for example 200)."));
            return;
        }
        m_predicted = unitOf(m_lesson.claims[static_cast<std::size_t>(q.claim)]).fromShown(value);
    } else {
        const int id = m_choices->checkedId();
        if (id < 0) {
            m_result->setText(tr("Pick an answer first."));
            return;
        }
        m_predicted = q.values[static_cast<std::size_t>(id)];
    }
    // The claim's own rule, on the scene with the settings the student runs,
    // measured on a worker thread: a claim may take seconds.
    const sim::Claim claim = m_lesson.claims[static_cast<std::size_t>(q.claim)];
    sim::Scene scene = m_lesson.scene;
    scene.settings = m_controller->world().settings();
    if (m_watcher.isRunning()) { // the last one is still stopping
        m_predicted.reset();
        m_result->setText(tr("Still stopping the last measurement; try again in a moment."));
        return;
    }
    setAnswerEnabled(false);
    m_run->setEnabled(false);
    m_progress->setValue(0);
    m_progress->show();
    m_cancel->show();
    m_cancel->setEnabled(true);
    m_result->setText(tr("Locked in. Working out the answer…"));
    m_cancelFlag = false;
    m_discard = false;
    auto progress = [this, flag = &m_cancelFlag, shown = -1](double done) mutable {
        const int percent = static_cast<int>(100.0 * done);
        if (percent != shown) {
            shown = percent;
            QMetaObject::invokeMethod(this, [this, percent] { m_progress->setValue(percent); }, Qt::QueuedConnection);
        }
        return !flag->load();
    };
    m_watcher.setFuture(QtConcurrent::run([scene, claim, progress]() mutable {
        return sim::checkClaim(scene, claim, progress);
    }));
}

void PredictDock::cancelMeasurement()
{
    m_cancelFlag = true;
    m_cancel->setEnabled(false);
}

void PredictDock::setAnswerEnabled(bool enabled)
{
    m_number->setEnabled(enabled);
    for (QAbstractButton* b : m_choices->buttons())
        b->setEnabled(enabled);
}

void PredictDock::measurementFinished()
{
    m_progress->hide();
    m_cancel->hide();
    // showQuestion() has already asked again (also when the result was on
    // its way as the question reset: then nothing is predicted any more).
    if (m_discard || !m_predicted) {
        m_discard = false;
        return;
    }
    const sim::ClaimResult result = m_watcher.result();
    if (result.cancelled) {
        m_predicted.reset();
        setAnswerEnabled(true);
        m_run->setEnabled(true);
        m_result->setText(tr("Cancelled. Change your answer or lock it in again."));
        return;
    }
    const Prediction& q = m_lesson.predict[static_cast<std::size_t>(m_question)];
    const sim::Claim& claim = m_lesson.claims[static_cast<std::size_t>(q.claim)];
    m_measured = result.measured;
    m_revealAt = m_controller->world().time() + claim.at;
    m_show->setEnabled(true);
    m_result->setText(tr("Locked in. Watch: the answer comes at t = %1 s.").arg(number(m_revealAt)));
    m_controller->play();
}

void PredictDock::onStepped()
{
    if (m_predicted && !m_revealed && m_controller->world().time() >= m_revealAt - 1e-9)
        reveal();
}

void PredictDock::reveal()
{
    if (!m_predicted || m_revealed || m_lesson.predict.empty())
        return;
    m_revealed = true;
    m_show->setEnabled(false);
    const Prediction& q = m_lesson.predict[static_cast<std::size_t>(m_question)];
    const sim::Claim& claim = m_lesson.claims[static_cast<std::size_t>(q.claim)];
    const ShownUnit shown = unitOf(claim);
    const QString unit = shown.text;
    // The student reads the lesson's own sentence the answer checks, not
    // the measurement table's rule (written for lesson authors).
    const QString sentence = QString::fromStdString(claim.text).toHtmlEscaped();
    const double measured = *m_measured;
    if (!std::isfinite(measured)) {
        m_result->setText(tr("It could not be measured in this run (the lesson's sentence “%1”). Did a setting change it?")
                              .arg(sentence));
        return;
    }
    QString text;
    if (!q.choices.isEmpty()) {
        // The answer is the choice nearest to the measurement.
        std::size_t best = 0;
        for (std::size_t k = 1; k < q.values.size(); ++k)
            if (std::abs(q.values[k] - measured) < std::abs(q.values[best] - measured))
                best = k;
        const int chosen = m_choices->checkedId();
        const bool right = chosen == static_cast<int>(best);
        text = tr("You chose <b>%1</b>. Measured: <b>%2 %3</b>, so the answer is <b>%4</b>. %5")
                   .arg(q.choices.value(chosen).toHtmlEscaped(), number(shown.toShown(measured)), unit,
                        q.choices.value(static_cast<qsizetype>(best)).toHtmlEscaped(),
                        right ? tr("Well predicted!") : tr("Why was it different?"));
    } else {
        const double off = *m_predicted - measured;
        const QString share = measured != 0.0 ? tr(" (%1%)").arg(std::abs(100.0 * off / measured), 0, 'f', 0) : QString();
        text = tr("You said <b>%1 %2</b>. Measured: <b>%3 %2</b>. You were %4 %2 off%5.")
                   .arg(number(shown.toShown(*m_predicted)), unit, number(shown.toShown(measured)),
                        number(std::abs(shown.toShown(off))), share);
    }
    m_result->setText(text + tr("<br><small>The run measured what the lesson says: “%1”.</small>").arg(sentence));
}

void PredictDock::unitsChanged()
{
    if (m_lesson.predict.empty())
        return;
    const Prediction& q = m_lesson.predict[static_cast<std::size_t>(m_question)];
    m_unit->setText(unitOf(m_lesson.claims[static_cast<std::size_t>(q.claim)]).text);
}

void PredictDock::nextQuestion()
{
    if (m_lesson.predict.empty())
        return;
    m_question = (m_question + 1) % static_cast<int>(m_lesson.predict.size());
    showQuestion();
}

} // namespace forcelab

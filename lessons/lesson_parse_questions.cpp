// The predict and compare sections of a lesson file: questions answered by
// claims, and panes that run the scene with other settings side by side.

#include "lesson_parse_sections.h"

namespace forcelab::lessons::parsing {

namespace {

/// {"ask": "How high …?", "claim": 0, "choices": [{"label": "…", "value": 0}, …]}:
/// one question, answered by the claim with that index.
Prediction parseQuestion(Reader& r, const QJsonObject& o, const QString& p, int claims)
{
    r.checkKeys(o, p, {"ask", "claim", "choices"});
    Prediction q;
    if (r.require(o, p, "ask", QStringLiteral("the question, e.g. \"How high will the ball rise?\"")))
        r.string(o, p, "ask", q.ask);
    if (r.require(o, p, "claim", QStringLiteral("the index of the claim whose measurement answers it"))) {
        if (claims == 0)
            r.fail(join(p, "claim"), QStringLiteral("the lesson has no claims to answer the question"));
        else
            r.integer(o, p, "claim", 0, claims - 1, q.claim);
    }
    if (const auto c = r.array(o, p, "choices", QStringLiteral("an array of {\"label\": …, \"value\": …}"))) {
        const QString cp = join(p, "choices");
        if (c->size() < 2 || c->size() > 8)
            r.fail(cp, QStringLiteral("%1 %2; give 2 to 8").arg(c->size()).arg(c->size() == 1 ? "choice" : "choices"));
        for (qsizetype k = 0; k < c->size(); ++k) {
            const QString kp = join(cp, k);
            if (!c->at(k).isObject()) {
                r.fail(kp, QStringLiteral("expected {\"label\": …, \"value\": …}, got ") + describe(c->at(k)));
                continue;
            }
            const QJsonObject choice = c->at(k).toObject();
            r.checkKeys(choice, kp, {"label", "value"});
            QString label;
            double value = 0.0;
            r.require(choice, kp, "label", QStringLiteral("the answer as the student reads it"));
            r.require(choice, kp, "value", QStringLiteral("the answer in the claim's unit"));
            if (r.string(choice, kp, "label", label) && r.number(choice, kp, "value", range::kClaimNumber, value)) {
                q.choices << label;
                q.values.push_back(value);
            }
        }
    }
    return q;
}

} // namespace

/// [{"ask": "How high …?", "claim": 0}, {"ask": "…", "claim": 1, "choices":
/// [{"label": "…", "value": 0}, …]}]: each question is answered by a claim.
void parsePredict(Reader& r, const QJsonArray& a, int claims, std::vector<Prediction>& out)
{
    objectList(r, a, QStringLiteral("predict"), kMaxListEntries, "entries",
               QStringLiteral("a question {\"ask\": …, \"claim\": …}"), out,
               [&](const QJsonObject& o, const QString& p) { return parseQuestion(r, o, p, claims); });
}

/// [{"label": "mirror", "set": {"world.wall_model": "mirror"}}, …]
void parseCompare(Reader& r, const QJsonArray& a, std::vector<ComparePane>& out)
{
    objectList(r, a, QStringLiteral("compare"), Lesson::kMaxComparePanes, "panes",
               QStringLiteral("a pane {\"label\": …, \"set\": {…}}"), out,
               [&](const QJsonObject& o, const QString& p) {
                   r.checkKeys(o, p, {"label", "set"});
                   ComparePane pane;
                   if (r.require(o, p, "label", QStringLiteral("the pane's name, e.g. \"mirror\"")))
                       r.string(o, p, "label", pane.label);
                   if (r.require(o, p, "set", QStringLiteral("the settings this pane runs with, {\"key.path\": value}")))
                       if (const auto set = r.object(o, p, "set"))
                           parseSet(r, *set, join(p, "set"), pane.set);
                   return pane;
               });
}

} // namespace forcelab::lessons::parsing

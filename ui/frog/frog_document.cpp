#include "ui/frog/frog_document.h"

#include "core/softbody/step_pacer.h"
#include "ui/common/error_text.h"
#include "ui/frog/frog_json.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace granota::ui {

// The messages are the Frog tab's: translated in its context (translations/granota_ca.ts).

namespace {

bool refuse(QString* error, const QString& text)
{
    if (error)
        *error = text;
    return false;
}

/// The largest coordinate of a ruler's end, scene px.
constexpr double kMaxRulerCoordinate = 1e7;

/// "params": the scene file's keys over `spec`, checked once together (withParameters).
bool readParams(const QJsonValue& params, const QString& name, SceneSpec& spec, QString* error)
{
    if (!params.isObject())
        return refuse(error, QCoreApplication::translate("granota::ui::FrogTab", "The frog's parameters must be an object."));
    std::vector<std::pair<std::string, Json>> values;
    const QJsonObject p = params.toObject();
    for (auto it = p.begin(); it != p.end(); ++it) {
        if (!spec.hasParam(it.key().toStdString()))
            return refuse(
                error,
                QCoreApplication::translate("granota::ui::FrogTab", "Scene “%1” has no parameter “%2”.").arg(name, it.key()));
        values.emplace_back(it.key().toStdString(), fromQJson(it.value()));
    }
    auto changed = withParameters(spec, values);
    if (!changed)
        return refuse(error, QCoreApplication::translate("granota::ui::FrogTab", "This value was refused: %1")
                                 .arg(ErrorText::of(changed.error())));
    spec = std::move(changed).value();
    return true;
}

bool readOverlays(const QJsonValue& v, FrogOverlays& overlays, QString* error)
{
    if (!v.isObject())
        return refuse(error, QCoreApplication::translate("granota::ui::FrogTab", "The frog's overlays must be an object."));
    const QJsonObject o = v.toObject();
    for (const FrogOverlay& overlay : frogOverlays()) {
        const QJsonValue f = o.value(QLatin1String(overlay.key));
        if (f.isUndefined())
            continue;
        if (!f.isBool())
            return refuse(error, QCoreApplication::translate("granota::ui::FrogTab", "The overlay “%1” must be true or false.")
                                     .arg(QLatin1String(overlay.key)));
        overlays.*overlay.flag = f.toBool();
    }
    return true;
}

} // namespace

QString frogSceneLoadError(const QString& name, const Error& coreError)
{
    QStringList names;
    for (const std::string& n : sceneNames())
        names << QString::fromStdString(n);
    // A known scene that fails to load is a fault in its file (or in how it is read):
    // the core's own message says which, and hiding it behind "unknown" hides the cause.
    // A fault of the installation's own file is named in the core's words, as a report would
    // quote them; a refusal the core names a sentence for is said in the interface's language.
    if (names.contains(name))
        return QCoreApplication::translate("granota::ui::FrogTab", "The scene “%1” cannot be loaded: %2")
            .arg(name, coreError.id == MessageId::None ? QString::fromStdString(coreError.message) : ErrorText::of(coreError));
    return QCoreApplication::translate("granota::ui::FrogTab", "Unknown scene “%1”. The scenes are: %2.")
        .arg(name, names.join(QStringLiteral(", ")));
}

QJsonObject FrogDocument::toJson(const RecordedRun* run) const
{
    QJsonObject state;
    state.insert(QStringLiteral("scene"), QString::fromStdString(scene.name));
    state.insert(QStringLiteral("solver"), QString::fromStdString(solverName(solver)));
    state.insert(QStringLiteral("params"), toQJson(*sceneToJson(scene).find("params")));
    QJsonObject shown;
    for (const FrogOverlay& overlay : frogOverlays())
        shown.insert(QLatin1String(overlay.key), overlays.*overlay.flag);
    state.insert(QStringLiteral("overlays"), shown);
    state.insert(QStringLiteral("bezier_outline"), fitOutline ? QStringLiteral("fit") : QStringLiteral("precomputed"));
    state.insert(QStringLiteral("paused"), paused);
    state.insert(QStringLiteral("speed"), speed);
    if (ruler) // a measure shown goes with the document, as the overlays do
        state.insert(QStringLiteral("ruler"), QJsonArray{ruler->first.x, ruler->first.y, ruler->second.x, ruler->second.y});
    // The knobs the run started with; the recording's events turn them on the way.
    state.insert(QStringLiteral("stable"), toQJson(stableSettingsToJson(scene.stable)));
    // The run so far (docs/rewind.md): its events, how far it went, and the step shown.
    if (run)
        state.insert(QStringLiteral("recording"), documentRunToQJson(*run));
    return state;
}

std::optional<FrogDocument> FrogDocument::fromJson(const QJsonObject& state, const FrogDocument& current, QString* error)
{
    FrogDocument doc = current;
    doc.ruler.reset();
    doc.recording.reset();
    const QString name = state.value(QStringLiteral("scene")).toString();
    auto spec = loadScene(name.toStdString());
    if (!spec) {
        refuse(error, frogSceneLoadError(name, spec.error()));
        return std::nullopt;
    }
    doc.scene = std::move(spec).value();
    doc.solver = SolverKind::Seed;
    if (state.contains(QStringLiteral("solver"))) {
        const QString s = state.value(QStringLiteral("solver")).toString();
        auto kind = parseSolverKind(s.toStdString());
        if (!kind) {
            refuse(error, QCoreApplication::translate("granota::ui::FrogTab", "Unknown solver “%1” (seed or stable).").arg(s));
            return std::nullopt;
        }
        doc.solver = *kind;
    }
    if (state.contains(QStringLiteral("params")) && !readParams(state.value(QStringLiteral("params")), name, doc.scene, error))
        return std::nullopt;
    if (state.contains(QStringLiteral("overlays")) && !readOverlays(state.value(QStringLiteral("overlays")), doc.overlays, error))
        return std::nullopt;
    if (state.contains(QStringLiteral("bezier_outline"))) {
        const QString b = state.value(QStringLiteral("bezier_outline")).toString();
        if (b != QLatin1String("fit") && b != QLatin1String("precomputed")) {
            refuse(error, QCoreApplication::translate("granota::ui::FrogTab",
                                                      "The Bézier outline must be “precomputed” or “fit”, not “%1”.")
                              .arg(b));
            return std::nullopt;
        }
        doc.fitOutline = b == QLatin1String("fit");
    }
    if (state.contains(QStringLiteral("paused"))) {
        if (!state.value(QStringLiteral("paused")).isBool()) {
            refuse(error, QCoreApplication::translate("granota::ui::FrogTab", "“paused” must be true or false."));
            return std::nullopt;
        }
        doc.paused = state.value(QStringLiteral("paused")).toBool();
    }
    if (state.contains(QStringLiteral("speed"))) {
        const QJsonValue v = state.value(QStringLiteral("speed"));
        const auto& speeds = StepPacer::kSpeeds;
        if (!v.isDouble() || std::find(speeds.begin(), speeds.end(), v.toDouble()) == speeds.end()) {
            refuse(error,
                   QCoreApplication::translate("granota::ui::FrogTab", "The speed must be one of 0.125, 0.25, 0.5, 1, 2 and 4."));
            return std::nullopt;
        }
        doc.speed = v.toDouble();
    }
    // The stable solver's knobs, checked as a scene file's "stable" (from the defaults, as a
    // file's "stable" is read); without them, those of `current`.
    if (state.contains(QStringLiteral("stable"))) {
        doc.scene.stable = StableSettings();
        auto knobs = withStableSettings(doc.scene, fromQJson(state.value(QStringLiteral("stable"))));
        if (!knobs) {
            refuse(error, QCoreApplication::translate("granota::ui::FrogTab", "This value was refused: %1")
                              .arg(ErrorText::of(knobs.error())));
            return std::nullopt;
        }
        doc.scene = std::move(knobs).value();
    } else {
        doc.scene.stable = current.scene.stable;
    }
    // The ruler's ends, scene px: four finite numbers.
    if (state.contains(QStringLiteral("ruler"))) {
        const QJsonArray r = state.value(QStringLiteral("ruler")).toArray();
        const bool ok = r.size() == 4 && std::all_of(r.begin(), r.end(), [](const QJsonValue& v) {
                            return v.isDouble() && std::isfinite(v.toDouble()) && std::abs(v.toDouble()) <= kMaxRulerCoordinate;
                        });
        if (!ok) {
            refuse(error, QCoreApplication::translate("granota::ui::FrogTab",
                                                      "The ruler must be four numbers: x and y of each end, in px."));
            return std::nullopt;
        }
        doc.ruler = std::pair{Point(r[0].toDouble(), r[1].toDouble()), Point(r[2].toDouble(), r[3].toDouble())};
    }
    // The recorded run: checked whole before anything changes.
    if (state.contains(QStringLiteral("recording"))) {
        auto parsed = documentRunFromQJson(state.value(QStringLiteral("recording")));
        if (!parsed) {
            refuse(error, QCoreApplication::translate("granota::ui::FrogTab", "The frog's recording was refused: %1")
                              .arg(ErrorText::of(parsed.error())));
            return std::nullopt;
        }
        doc.recording = std::move(parsed).value();
    }
    return doc;
}

} // namespace granota::ui

#include "app/cli/simulate_request.h"

#include <QHash>

#include "app/cli/command_parser.h"
#include "app/cli/simulate_checks.h"
#include "app/cli/simulate_cnc.h"
#include "core/control/integral_action.h"
#include "core/control/run_to_run_plant.h"
#include "core/loop/adaptation_config.h"
#include "core/run/run_limits.h"
#include "core/sim/shaft/plant_mismatch.h"

namespace tt::cli {

namespace {

/// Fewest parts counted in a run through a CNC (each takes wall time; the statistics need a few after the start-up).
constexpr std::int64_t kMinCncParts = 10;

/// The request field each option sets.
const QHash<QString, QString>& optionOfField() {
    static const QHash<QString, QString> map{
        {QStringLiteral("preset"), QStringLiteral("--preset")},
        {QStringLiteral("delay"), QStringLiteral("--delay")},
        {QStringLiteral("controller"), QStringLiteral("--controller")},
        {QStringLiteral("ewma_weight"), QStringLiteral("--ewma-weight")},
        {QStringLiteral("drift_weight"), QStringLiteral("--drift-weight")},
        {QStringLiteral("integral.weight"), QStringLiteral("--integral-weight")},
        {QStringLiteral("mismatch_action"), QStringLiteral("--mismatch-action")},
        {QStringLiteral("dither_share"), QStringLiteral("--dither-share")},
        {QStringLiteral("plant_mismatch.gain_factor"), QStringLiteral("--plant-gain")},
        {QStringLiteral("plant_mismatch.delay"), QStringLiteral("--plant-delay")},
        {QStringLiteral("plant_mismatch.step.at_part"), QStringLiteral("--step-at")},
        {QStringLiteral("plant_mismatch.step.size_mm"), QStringLiteral("--step-mm")},
        {QStringLiteral("plant_mismatch.step.point"), QStringLiteral("--step-point")},
        {QStringLiteral("seed"), QStringLiteral("--seed")},
        {QStringLiteral("speed"), QStringLiteral("--speed")},
        {QStringLiteral("end_part"), QStringLiteral("--parts")},
        {QStringLiteral("warmup_parts"), QStringLiteral("--warmup")},
        {QStringLiteral("cnc.url"), QStringLiteral("--cnc")},
        {QStringLiteral("cnc.mode"), QStringLiteral("--cnc-mode")},
        {QStringLiteral("cnc.program_folder"), QStringLiteral("--cnc-program-folder")}};
    return map;
}

void addPlantOptions(CommandParser& parser) {
    parser.addOption(QStringLiteral("plant-gain"),
                     QStringLiteral("The simulated plant's gain as a multiple of the model's k_i, 0.1..10 (default 1; "
                                    "statistical plant only)."),
                     QStringLiteral("k"));
    parser.addOption(QStringLiteral("plant-delay"),
                     QStringLiteral("The simulated plant's delay in parts, from the model's z to 8 (default: the "
                                    "model's)."),
                     QStringLiteral("z"));
    parser.addOption(QStringLiteral("step-at"),
                     QStringLiteral("A step in the plant from this part on, 1..10000000 (with --step-mm)."),
                     QStringLiteral("n"));
    parser.addOption(QStringLiteral("step-mm"), QStringLiteral("Size of the step in diameter, -1..1 mm, not 0."),
                     QStringLiteral("mm"));
    parser.addOption(QStringLiteral("step-point"),
                     QStringLiteral("The step at this control point only, 1..16 (default: the whole part)."),
                     QStringLiteral("i"));
}

void addControlOptions(CommandParser& parser) {
    parser.addOption(QStringLiteral("integral"),
                     QStringLiteral("Integral action of the LQG (an integrating disturbance state): on or off "
                                    "(default: the preset's)."),
                     QStringLiteral("on|off"));
    parser.addOption(QStringLiteral("integral-weight"),
                     QStringLiteral("Step variance of the integrating state as a share of the disturbance "
                                    "variance, 1e-6..1 (default: the preset's, 0.3)."),
                     QStringLiteral("w"));
    parser.addOption(QStringLiteral("drift-weight"),
                     QStringLiteral("Double EWMA: the drift weight lambda2 in (0, 1) (default 0.1; the offset's "
                                    "weight is --ewma-weight)."),
                     QStringLiteral("w"));
    parser.addOption(QStringLiteral("mismatch-action"),
                     QStringLiteral("When the plant no longer matches the model: adapt (switch to a robust fallback, "
                                    "identify the plant and apply a design whose margins hold), propose (the same, but "
                                    "the design waits for an engineer), hold (the CNC keeps the last correction) or "
                                    "alarm (alarm only); default: the preset's, adapt."),
                     QStringLiteral("adapt|propose|hold|alarm"));
    parser.addOption(QStringLiteral("dither-share"),
                     QStringLiteral("A dither on the correction while the loop identifies the plant: the diameter "
                                    "moves by +- this share of the tolerance zone, 0..0.5 (default: the preset's, 0: "
                                    "off)."),
                     QStringLiteral("s"));
}

void addSetupOptions(CommandParser& parser) {
    parser.addOption(QStringLiteral("preset"),
                     QStringLiteral("Scenario preset name or JSON file (default paper-2012; the physical lathe: "
                                    "paper-2012-group1..3)."),
                     QStringLiteral("name"), QStringLiteral("paper-2012"));
    parser.addOption(QStringLiteral("delay"),
                     QStringLiteral("Transport delay z in parts, 1..8 (default: the preset's)."), QStringLiteral("z"));
    parser.addOption(QStringLiteral("parts"),
                     QStringLiteral("Parts counted in the statistics (k_eff, variances), 100..10000000 (10.. with "
                                    "--cnc; default 20000); the warm-up parts are machined before them."),
                     QStringLiteral("n"), QStringLiteral("20000"));
    parser.addOption(
        QStringLiteral("warmup"),
        QStringLiteral("Parts machined first, 0..1000000 (default 100, 0 with --cnc): measured, stored and judged like "
                       "every part (the verdicts count them, their share apart) but not counted in the "
                       "statistics. --parts 150 machines 250 parts."),
        QStringLiteral("n"), QStringLiteral("100"));
    parser.addOption(QStringLiteral("seed"), QStringLiteral("Random seed, 0..2^53 (default 1)."), QStringLiteral("s"),
                     QStringLiteral("1"));
    parser.addOption(QStringLiteral("controller"),
                     QStringLiteral("lqg, ewma, dewma (double EWMA) or open (default lqg)."), QStringLiteral("kind"),
                     QStringLiteral("lqg"));
    parser.addOption(QStringLiteral("ewma-weight"),
                     QStringLiteral("EWMA weight in (0, 1], or auto: the best on a grid 0.05..1 (default: the "
                                    "preset's)."),
                     QStringLiteral("w"));
    parser.addOption(QStringLiteral("speed"),
                     QStringLiteral("Simulated time per wall time: 0 (the default: as fast as possible) or 1..1e9 "
                                    "(1: the lathe's own pace; 360: a 6-minute part per second)."),
                     QStringLiteral("x"), QStringLiteral("0"));
    parser.addOption(QStringLiteral("machine"),
                     QStringLiteral("The lathe's name stored with the run (a plant-wide history holds several)."),
                     QStringLiteral("name"));
}

void readEwmaWeight(const CommandParser& parser, runtime::RunRequest& q) {
    if (!parser.isSet(QStringLiteral("ewma-weight"))) return;
    if (q.controller != core::ControllerKind::Ewma && q.controller != core::ControllerKind::Dewma)
        throw UsageError("--ewma-weight: only with --controller ewma or dewma");
    if (parser.value(QStringLiteral("ewma-weight")) == QLatin1String("auto")) {
        q.ewmaAuto = true;
        return;
    }
    const double w = parser.number(QStringLiteral("ewma-weight"), 0.0, 1.0);
    if (w <= 0.0) throw UsageError("--ewma-weight: must be in (0, 1] or auto");
    q.ewmaWeight = w;
}

void readPlant(const CommandParser& parser, runtime::RunRequest& q) {
    if (parser.isSet(QStringLiteral("plant-gain")))
        q.plant.gainFactor =
            parser.number(QStringLiteral("plant-gain"), core::kMinPlantGainFactor, core::kMaxPlantGainFactor);
    if (parser.isSet(QStringLiteral("plant-delay")))
        q.plant.delayParts = static_cast<int>(parser.integer(QStringLiteral("plant-delay"), 1, core::kMaxDelay));
    if (parser.isSet(QStringLiteral("step-at")) != parser.isSet(QStringLiteral("step-mm")))
        throw UsageError("--step-at and --step-mm: give both (the part and the size of the step)");
    if (parser.isSet(QStringLiteral("step-point")) && !parser.isSet(QStringLiteral("step-at")))
        throw UsageError("--step-point: only with --step-at and --step-mm");
    if (!parser.isSet(QStringLiteral("step-at"))) return;
    runtime::RequestedStep step;
    step.atPart = parser.integer(QStringLiteral("step-at"), 1, 10000000);
    step.sizeMm = parser.number(QStringLiteral("step-mm"), -core::kMaxPlantStepMm, core::kMaxPlantStepMm);
    if (step.sizeMm == 0.0) throw UsageError("--step-mm: must not be 0");
    if (parser.isSet(QStringLiteral("step-point")))
        step.point = static_cast<int>(parser.integer(QStringLiteral("step-point"), 1, core::kMaxControlPoints));
    q.plant.step = step;
}

void readControl(const CommandParser& parser, runtime::RunRequest& q) {
    if (parser.isSet(QStringLiteral("integral")))
        q.integral = parser.choice(QStringLiteral("integral"), {QStringLiteral("on"), QStringLiteral("off")}) ==
                     QLatin1String("on");
    if (parser.isSet(QStringLiteral("integral-weight")))
        q.integralWeight =
            parser.number(QStringLiteral("integral-weight"), core::kMinIntegralWeight, core::kMaxIntegralWeight);
    if (parser.isSet(QStringLiteral("drift-weight"))) {
        if (q.controller != core::ControllerKind::Dewma)
            throw UsageError("--drift-weight: only with --controller dewma");
        const double w = parser.number(QStringLiteral("drift-weight"), 0.0, 0.999);
        if (w <= 0.0) throw UsageError("--drift-weight: must be in (0, 1)");
        q.driftWeight = w;
    }
    if (parser.isSet(QStringLiteral("mismatch-action")))
        q.mismatchAction =
            parser
                .choice(QStringLiteral("mismatch-action"), {QStringLiteral("adapt"), QStringLiteral("propose"),
                                                            QStringLiteral("hold"), QStringLiteral("alarm")})
                .toStdString();
    if (parser.isSet(QStringLiteral("dither-share")))
        q.ditherShare = parser.number(QStringLiteral("dither-share"), 0.0, core::kMaxDitherShare);
}

}  // namespace

void addRunRequestOptions(CommandParser& parser) {
    addSetupOptions(parser);
    addPlantOptions(parser);
    addControlOptions(parser);
    addCncOptions(parser);
}

std::optional<QString> runOptionGiven(const CommandParser& parser) {
    for (const char* option : {"preset",       "delay",        "parts",      "warmup",          "seed",
                               "controller",   "ewma-weight",  "plant-gain", "plant-delay",     "step-at",
                               "step-mm",      "step-point",   "integral",   "integral-weight", "mismatch-action",
                               "dither-share", "drift-weight", "cnc",        "cnc-mode",        "cnc-program-folder"})
        if (parser.isSet(QString::fromLatin1(option))) return QStringLiteral("--") + QString::fromLatin1(option);
    return std::nullopt;
}

runtime::RunRequest requestFromOptions(const CommandParser& parser, const QString& database) {
    runtime::RunRequest q;
    q.preset = parser.value(QStringLiteral("preset"));
    if (parser.isSet(QStringLiteral("delay")))
        q.delay = static_cast<int>(parser.integer(QStringLiteral("delay"), 1, core::kMaxDelay));
    // Through a CNC every part takes wall time: a shorter run, and no warm-up unless asked for.
    const bool cnc = parser.isSet(QStringLiteral("cnc"));
    const std::int64_t parts = parser.integer(QStringLiteral("parts"), cnc ? kMinCncParts : 100, core::kMaxRunParts);
    q.warmupParts = cnc && !parser.isSet(QStringLiteral("warmup"))
                        ? 0
                        : parser.integer(QStringLiteral("warmup"), 0, core::kMaxWarmupParts);
    q.endPart = q.warmupParts + parts;
    q.seed = static_cast<std::uint64_t>(parser.integer(QStringLiteral("seed"), 0, 1LL << 53));
    q.controller = core::controllerKindFromName(
        parser
            .choice(QStringLiteral("controller"),
                    {QStringLiteral("lqg"), QStringLiteral("ewma"), QStringLiteral("open"), QStringLiteral("dewma")})
            .toStdString());
    readEwmaWeight(parser, q);
    q.speed = simulationSpeed(parser);
    q.lathe = parser.value(QStringLiteral("machine"));
    q.database = database;
    readPlant(parser, q);
    readControl(parser, q);
    readCncOptions(parser, q);
    try {
        runtime::validate(q);
    } catch (const runtime::RunRequestError& e) {
        throw usageErrorOf(e);
    }
    return q;
}

UsageError usageErrorOf(const runtime::RunRequestError& error, const QString& source) {
    const QString field = QString::fromStdString(error.field);
    const std::string what = error.what();
    if (!source.isEmpty()) return UsageError(source.toStdString() + ": " + what);
    const auto option = optionOfField().find(field);
    if (option == optionOfField().end()) return UsageError(what);
    // "plant_mismatch.gain_factor: 12 is outside ..." -> "--plant-gain: 12 is outside ..."
    const std::string prefix = error.field + ": ";
    const std::string why = what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
    return UsageError(option->toStdString() + ": " + why);
}

}  // namespace tt::cli

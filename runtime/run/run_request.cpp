#include "runtime/run/run_request.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QSet>
#include <cmath>

#include "config/controller_tuning_json.h"
#include "core/common/bounded_input.h"
#include "core/loop/adaptation_config.h"
#include "core/loop/mismatch_monitor.h"
#include "core/run/run_limits.h"

namespace tt::runtime {

namespace {

/// Largest request file read (a request is a few kB; a tuning with eight components per point stays far below).
constexpr std::size_t kMaxRequestBytes = 1u << 20;
/// Parts a run may end after at most: the longest study and its warm-up.
constexpr std::int64_t kMaxEndPart = core::kMaxRunParts + core::kMaxWarmupParts;

[[noreturn]] void refuse(const std::string& field, const std::string& why) {
    throw RunRequestError(field, why);
}

std::string number(double v) {
    QString s = QString::number(v, 'g', 10);
    return s.toStdString();
}

void requireRange(const std::string& field, double v, double lo, double hi) {
    if (!std::isfinite(v) || v < lo || v > hi)
        refuse(field, number(v) + " is outside " + number(lo) + " .. " + number(hi));
}

bool isEwma(core::ControllerKind k) {
    return k == core::ControllerKind::Ewma || k == core::ControllerKind::Dewma;
}

// ---- reading JSON, field by field ------------------------------------------------------------------------

/// The keys one object may hold; anything else is refused by name (a typo is not silently a default).
void onlyKeys(const QJsonObject& o, const std::string& where, std::initializer_list<const char*> keys) {
    QSet<QString> allowed;
    for (const char* k : keys)
        allowed.insert(QString::fromLatin1(k));
    for (auto it = o.begin(); it != o.end(); ++it)
        if (!allowed.contains(it.key()))
            refuse(where.empty() ? it.key().toStdString() : where + "." + it.key().toStdString(), "unknown field");
}

class Reader {
public:
    Reader(const QJsonObject& o, std::string where) : m_o(o), m_where(std::move(where)) {}
    std::string field(const char* key) const { return m_where.empty() ? key : m_where + "." + key; }
    bool has(const char* key) const { return m_o.contains(QLatin1String(key)); }
    QJsonValue value(const char* key) const { return m_o.value(QLatin1String(key)); }

    QString text(const char* key, const QString& fallback) const {
        if (!has(key)) return fallback;
        if (!value(key).isString()) refuse(field(key), "must be a string");
        return value(key).toString();
    }
    std::optional<double> number(const char* key) const {
        if (!has(key)) return std::nullopt;
        if (!value(key).isDouble()) refuse(field(key), "must be a number");
        return value(key).toDouble();
    }
    std::optional<std::int64_t> whole(const char* key) const {
        const std::optional<double> v = number(key);
        if (!v) return std::nullopt;
        if (std::floor(*v) != *v) refuse(field(key), "must be a whole number");
        if (std::abs(*v) >= 9.2e18) refuse(field(key), "is too large");
        return static_cast<std::int64_t>(*v);
    }
    std::optional<bool> flag(const char* key) const {
        if (!has(key)) return std::nullopt;
        if (!value(key).isBool()) refuse(field(key), "must be true or false");
        return value(key).toBool();
    }
    QJsonObject object(const char* key) const {
        if (!has(key)) return {};
        if (!value(key).isObject()) refuse(field(key), "must be an object");
        return value(key).toObject();
    }

private:
    QJsonObject m_o;
    std::string m_where;
};

void readController(const Reader& r, RunRequest& q) {
    try {
        q.controller = core::controllerKindFromName(r.text("controller", QStringLiteral("lqg")).toStdString());
    } catch (const std::invalid_argument&) {
        refuse("controller", "must be one of lqg, ewma, dewma, open");
    }
    if (r.has("ewma_weight") && r.value("ewma_weight").isString()) {
        if (r.value("ewma_weight").toString() != QLatin1String("auto"))
            refuse("ewma_weight", "must be a number in (0, 1] or \"auto\"");
        q.ewmaAuto = true;
    } else {
        q.ewmaWeight = r.number("ewma_weight");
    }
    q.driftWeight = r.number("drift_weight");
    if (const QJsonObject integral = r.object("integral"); !integral.isEmpty()) {
        onlyKeys(integral, "integral", {"enabled", "weight"});
        const Reader i(integral, "integral");
        q.integral = i.flag("enabled");
        q.integralWeight = i.number("weight");
    }
    if (r.has("mismatch_action")) q.mismatchAction = r.text("mismatch_action", {}).toStdString();
    q.ditherShare = r.number("dither_share");
    if (r.has("tuning")) q.tuning = r.object("tuning");
}

void readPlant(const Reader& r, RunRequest& q) {
    const QJsonObject plant = r.object("plant_mismatch");
    if (plant.isEmpty()) return;
    onlyKeys(plant, "plant_mismatch", {"gain_factor", "delay", "step"});
    const Reader p(plant, "plant_mismatch");
    q.plant.gainFactor = p.number("gain_factor");
    if (const auto d = p.whole("delay")) q.plant.delayParts = static_cast<int>(*d);
    const QJsonObject step = p.object("step");
    if (step.isEmpty()) return;
    onlyKeys(step, "plant_mismatch.step", {"at_part", "size_mm", "point"});
    const Reader s(step, "plant_mismatch.step");
    RequestedStep st;
    const auto at = s.whole("at_part");
    const auto size = s.number("size_mm");
    if (!at || !size) refuse("plant_mismatch.step", "needs at_part and size_mm");
    st.atPart = *at;
    st.sizeMm = *size;
    if (const auto point = s.whole("point")) st.point = static_cast<int>(*point);
    q.plant.step = st;
}

void readCnc(const Reader& r, RunRequest& q) {
    const QJsonObject cnc = r.object("cnc");
    if (cnc.isEmpty()) return;
    onlyKeys(cnc, "cnc", {"url", "mode", "program_folder"});
    const Reader c(cnc, "cnc");
    q.cnc = c.text("url", {});
    q.cncMode = c.text("mode", {});
    q.cncProgramFolder = c.text("program_folder", {});
}

void readRun(const Reader& r, RunRequest& q) {
    if (const auto seed = r.whole("seed")) {
        if (*seed < 0) refuse("seed", "must not be negative");
        q.seed = static_cast<std::uint64_t>(*seed);
    }
    q.speed = r.number("speed").value_or(0.0);
    q.endPart = r.whole("end_part");
    q.warmupParts = r.whole("warmup_parts").value_or(0);
    q.manualEntry = r.flag("manual_entry").value_or(false);
    q.pauseOnScrap = r.flag("pause_on_scrap").value_or(false);
    q.database = r.text("database", {});
}

// ---- checks that need the scenario ----------------------------------------------------------------------

void validatePlant(const RunRequest& q, const config::LoopScenario& scenario) {
    const RequestedPlant& p = q.plant;
    if (p.gainFactor)
        requireRange("plant_mismatch.gain_factor", *p.gainFactor, core::kMinPlantGainFactor, core::kMaxPlantGainFactor);
    if (p.delayParts && (*p.delayParts < scenario.delay() || *p.delayParts > core::kMaxDelay))
        refuse("plant_mismatch.delay", std::to_string(*p.delayParts) + " is outside the model's delay " +
                                           std::to_string(scenario.delay()) + " .. " + std::to_string(core::kMaxDelay));
    if (p.step) {
        if (p.step->atPart < 1 || p.step->atPart > 10'000'000)
            refuse("plant_mismatch.step.at_part", std::to_string(p.step->atPart) + " is outside 1 .. 10000000");
        requireRange("plant_mismatch.step.size_mm", p.step->sizeMm, -core::kMaxPlantStepMm, core::kMaxPlantStepMm);
        if (p.step->sizeMm == 0.0) refuse("plant_mismatch.step.size_mm", "must not be 0");
        const int points = static_cast<int>(scenario.control.plant.points.size());
        if (p.step->point && (*p.step->point < 1 || *p.step->point > points))
            refuse("plant_mismatch.step.point",
                   std::to_string(*p.step->point) + " is outside 1 .. " + std::to_string(points));
    }
    if (scenario.lathe && ((p.gainFactor && *p.gainFactor != 1.0) || (p.step && p.step->point)))
        refuse(p.gainFactor ? "plant_mismatch.gain_factor" : "plant_mismatch.step.point",
               "simulated on the statistical plant only (a preset without a lathe section)");
}

void validateController(const RunRequest& q) {
    if (q.ewmaWeight && !isEwma(q.controller)) refuse("ewma_weight", "only with the ewma or dewma controller");
    if (q.ewmaAuto && !isEwma(q.controller)) refuse("ewma_weight", "only with the ewma or dewma controller");
    if (q.ewmaWeight && (!(*q.ewmaWeight > 0.0) || *q.ewmaWeight > 1.0))
        refuse("ewma_weight", number(*q.ewmaWeight) + " is outside (0, 1]");
    if (q.driftWeight && q.controller != core::ControllerKind::Dewma)
        refuse("drift_weight", "only with the dewma controller");
    if (q.driftWeight && (!(*q.driftWeight > 0.0) || *q.driftWeight >= 1.0))
        refuse("drift_weight", number(*q.driftWeight) + " is outside (0, 1)");
    if (q.integralWeight)
        requireRange("integral.weight", *q.integralWeight, core::kMinIntegralWeight, core::kMaxIntegralWeight);
    if (q.mismatchAction) try {
            core::mismatchActionFromName(*q.mismatchAction);
        } catch (const std::invalid_argument& e) {
            refuse("mismatch_action", e.what());
        }
    if (q.ditherShare) requireRange("dither_share", *q.ditherShare, 0.0, core::kMaxDitherShare);
}

void validateRun(const RunRequest& q) {
    if (q.machine.isEmpty()) refuse("machine", "must name a machine");
    if (q.preset.isEmpty()) refuse("preset", "must name a preset or a preset file");
    if (q.delay && (*q.delay < 1 || *q.delay > core::kMaxDelay))
        refuse("delay", std::to_string(*q.delay) + " is outside 1 .. " + std::to_string(core::kMaxDelay));
    if (q.seed > kMaxRequestSeed) refuse("seed", "is above 2^53");
    try {
        core::checkRunSpeed(q.speed);
    } catch (const std::invalid_argument& e) {
        refuse("speed", e.what());
    }
    if (q.endPart && (*q.endPart < 1 || *q.endPart > kMaxEndPart))
        refuse("end_part", std::to_string(*q.endPart) + " is outside 1 .. " + std::to_string(kMaxEndPart));
    if (q.warmupParts < 0 || q.warmupParts > core::kMaxWarmupParts)
        refuse("warmup_parts",
               std::to_string(q.warmupParts) + " is outside 0 .. " + std::to_string(core::kMaxWarmupParts));
    if (q.endPart && q.warmupParts >= *q.endPart)
        refuse("warmup_parts", "must be fewer than the run's parts (end_part " + std::to_string(*q.endPart) + ")");
}

void validateCnc(const RunRequest& q) {
    if (q.cnc.isEmpty()) {
        if (!q.cncMode.isEmpty()) refuse("cnc.mode", "only with a CNC (cnc.url)");
        if (!q.cncProgramFolder.isEmpty()) refuse("cnc.program_folder", "only with a CNC (cnc.url)");
        return;
    }
    if (const auto problem = cncUrlProblem(q.cnc)) refuse("cnc.url", *problem);
    if (!q.cncMode.isEmpty() && q.cncMode != QLatin1String("profile") && q.cncMode != QLatin1String("wear"))
        refuse("cnc.mode", QStringLiteral("'%1' is not profile or wear").arg(q.cncMode).toStdString());
    if (!q.cncProgramFolder.isEmpty() && !QFileInfo(q.cncProgramFolder).isDir())
        refuse("cnc.program_folder", QStringLiteral("'%1' is not a folder").arg(q.cncProgramFolder).toStdString());
    if (q.speed != 0.0) refuse("speed", "a run through a CNC goes at the machine's own pace; leave the speed at 0");
}

}  // namespace

std::optional<std::string> cncUrlProblem(const QString& url) {
    // linuxcnc://HOST or linuxcnc://HOST:PORT (HOST a name, an IPv4 address or an [IPv6] address).
    static const QRegularExpression form(
        QStringLiteral("^linuxcnc://([A-Za-z0-9._~%-]+|\\[[0-9A-Fa-f:.]+\\])(?::([^/?#]*))?$"));
    const QRegularExpressionMatch m = form.match(url);
    if (!m.hasMatch())
        return QStringLiteral("'%1' is not linuxcnc://HOST[:PORT] (the only CNC known is LinuxCNC)")
            .arg(url)
            .toStdString();
    if (m.capturedStart(2) < 0) return std::nullopt;
    bool ok = false;
    const int port = m.captured(2).toInt(&ok);
    if (!ok || port < 1 || port > 65535)
        return QStringLiteral("the port '%1' of '%2' is not 1 .. 65535").arg(m.captured(2), url).toStdString();
    return std::nullopt;
}

void validate(const RunRequest& request) {
    validateRun(request);
    validateController(request);
    validateCnc(request);
    scenarioOf(request);  // the preset, the tuning and the plant's difference, checked against each other
}

QJsonObject toJson(const RunRequest& q) {
    QJsonObject o{{QStringLiteral("machine"), q.machine},
                  {QStringLiteral("preset"), q.preset},
                  {QStringLiteral("controller"), QString::fromStdString(core::controllerKindName(q.controller))},
                  {QStringLiteral("seed"), static_cast<qint64>(q.seed)},
                  {QStringLiteral("speed"), q.speed}};
    if (!q.lathe.isEmpty()) o.insert(QStringLiteral("lathe"), q.lathe);
    if (!q.cncOutput.isEmpty() || !q.gauge.isEmpty())
        o.insert(QStringLiteral("devices"),
                 QJsonObject{{QStringLiteral("cnc_output"), q.cncOutput}, {QStringLiteral("gauge"), q.gauge}});
    if (!q.cnc.isEmpty() || !q.cncMode.isEmpty() || !q.cncProgramFolder.isEmpty()) {
        QJsonObject cnc{{QStringLiteral("url"), q.cnc}};
        if (!q.cncMode.isEmpty()) cnc.insert(QStringLiteral("mode"), q.cncMode);
        if (!q.cncProgramFolder.isEmpty()) cnc.insert(QStringLiteral("program_folder"), q.cncProgramFolder);
        o.insert(QStringLiteral("cnc"), cnc);
    }
    if (q.delay) o.insert(QStringLiteral("delay"), *q.delay);
    if (q.ewmaAuto) o.insert(QStringLiteral("ewma_weight"), QStringLiteral("auto"));
    if (q.ewmaWeight) o.insert(QStringLiteral("ewma_weight"), *q.ewmaWeight);
    if (q.driftWeight) o.insert(QStringLiteral("drift_weight"), *q.driftWeight);
    QJsonObject integral;
    if (q.integral) integral.insert(QStringLiteral("enabled"), *q.integral);
    if (q.integralWeight) integral.insert(QStringLiteral("weight"), *q.integralWeight);
    if (!integral.isEmpty()) o.insert(QStringLiteral("integral"), integral);
    if (q.mismatchAction) o.insert(QStringLiteral("mismatch_action"), QString::fromStdString(*q.mismatchAction));
    if (q.ditherShare) o.insert(QStringLiteral("dither_share"), *q.ditherShare);
    QJsonObject plant;
    if (q.plant.gainFactor) plant.insert(QStringLiteral("gain_factor"), *q.plant.gainFactor);
    if (q.plant.delayParts) plant.insert(QStringLiteral("delay"), *q.plant.delayParts);
    if (q.plant.step) {
        QJsonObject step{{QStringLiteral("at_part"), static_cast<qint64>(q.plant.step->atPart)},
                         {QStringLiteral("size_mm"), q.plant.step->sizeMm}};
        if (q.plant.step->point) step.insert(QStringLiteral("point"), *q.plant.step->point);
        plant.insert(QStringLiteral("step"), step);
    }
    if (!plant.isEmpty()) o.insert(QStringLiteral("plant_mismatch"), plant);
    if (q.tuning) o.insert(QStringLiteral("tuning"), *q.tuning);
    if (q.pauseOnScrap) o.insert(QStringLiteral("pause_on_scrap"), true);
    if (q.endPart) o.insert(QStringLiteral("end_part"), static_cast<qint64>(*q.endPart));
    if (q.warmupParts) o.insert(QStringLiteral("warmup_parts"), static_cast<qint64>(q.warmupParts));
    if (q.manualEntry) o.insert(QStringLiteral("manual_entry"), true);
    if (!q.database.isEmpty()) o.insert(QStringLiteral("database"), q.database);
    return o;
}

RunRequest runRequestFromJson(const QJsonObject& json) {
    onlyKeys(json, {},
             {"machine",        "lathe",        "devices",        "cnc",      "preset",          "delay",
              "controller",     "ewma_weight",  "drift_weight",   "integral", "mismatch_action", "dither_share",
              "plant_mismatch", "tuning",       "pause_on_scrap", "seed",     "speed",           "end_part",
              "warmup_parts",   "manual_entry", "database"});
    const Reader r(json, {});
    RunRequest q;
    q.machine = r.text("machine", kBuiltInLatheKey);
    q.lathe = r.text("lathe", {});
    if (const QJsonObject devices = r.object("devices"); !devices.isEmpty()) {
        onlyKeys(devices, "devices", {"cnc_output", "gauge"});
        const Reader d(devices, "devices");
        q.cncOutput = d.text("cnc_output", {});
        q.gauge = d.text("gauge", {});
    }
    readCnc(r, q);
    q.preset = r.text("preset", q.preset);
    if (const auto delay = r.whole("delay")) q.delay = static_cast<int>(*delay);
    readController(r, q);
    readPlant(r, q);
    readRun(r, q);
    return q;
}

RunRequest readRunRequestFile(const QString& path) {
    std::string text;
    try {
        text = core::readBoundedFile(path.toStdString(), {kMaxRequestBytes, 0, 0});
    } catch (const std::exception& e) {
        refuse("request", e.what());
    }
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(text), &error);
    if (error.error != QJsonParseError::NoError)
        refuse("request", QStringLiteral("'%1' is not JSON: %2 at offset %3")
                              .arg(path, error.errorString())
                              .arg(error.offset)
                              .toStdString());
    if (!doc.isObject()) refuse("request", QStringLiteral("'%1' must hold one JSON object").arg(path).toStdString());
    return runRequestFromJson(doc.object());
}

config::LoopScenario scenarioOf(const RunRequest& q) {
    config::LoopScenario scenario;
    try {
        scenario = config::loadLoopScenario(q.preset, q.delay);
    } catch (const std::invalid_argument& e) {
        refuse("preset", e.what());
    }
    if (q.tuning) try {
            const core::RunToRunSetup tuned = config::tunedSetupFromJson(*q.tuning, scenario.control);
            static_cast<core::ShaftScenario&>(scenario) = core::withControllerTuning(scenario, tuned);
        } catch (const std::invalid_argument& e) {
            refuse("tuning", e.what());
        }
    if (q.ewmaAuto) scenario.control.ewmaWeightAuto = true;
    if (q.integral) scenario.control.integral.enabled = *q.integral;
    if (q.integralWeight) scenario.control.integral.weight = *q.integralWeight;
    if (q.driftWeight) scenario.control.ewma.driftWeight = *q.driftWeight;
    if (q.mismatchAction) scenario.mismatchMonitor.action = core::mismatchActionFromName(*q.mismatchAction);
    if (q.ditherShare) scenario.adaptation.ditherShare = *q.ditherShare;
    scenario.pauseOnScrap = scenario.pauseOnScrap || q.pauseOnScrap;
    validatePlant(q, scenario);
    if (!q.cnc.isEmpty() && !scenario.lathe)
        refuse("preset", "a run through a CNC needs a preset with a lathe section (such as paper-2012-group1)");
    core::PlantMismatch& m = scenario.plantMismatch;
    if (q.plant.gainFactor) m.gainFactor = *q.plant.gainFactor;
    if (q.plant.delayParts) m.delayParts = q.plant.delayParts;
    if (q.plant.step)
        m.step = core::PlantStep{q.plant.step->atPart, q.plant.step->sizeMm,
                                 q.plant.step->point ? std::optional<int>(*q.plant.step->point - 1) : std::nullopt};
    return scenario;
}

core::ShaftRunChoice choiceOf(const RunRequest& q) {
    return {q.controller, q.ewmaWeight, q.endPart};
}

}  // namespace tt::runtime

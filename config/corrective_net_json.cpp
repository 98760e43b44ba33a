#include "config/corrective_net_json.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <cmath>
#include <stdexcept>

#include "config/json_section.h"

namespace tt::config {

namespace {

const QString kFormat = QStringLiteral("trueturn-corrective-net");
constexpr int kVersion = 1;

QJsonArray numbers(const double* values, Eigen::Index count) {
    QJsonArray a;
    for (Eigen::Index i = 0; i < count; ++i)
        a.append(values[i]);
    return a;
}

QJsonArray numbers(const std::vector<double>& v) {
    return numbers(v.data(), static_cast<Eigen::Index>(v.size()));
}

// An array of `count` finite numbers (count < 0: any length) at `key` of `s`.
std::vector<double> readNumbers(const JsonSection& s, const QString& key, int count) {
    const QJsonValue v = s.value(key);
    if (!v.isArray()) s.fail(key, "must be an array of numbers");
    std::vector<double> out;
    for (const QJsonValue& item : v.toArray()) {
        if (!item.isDouble() || !std::isfinite(item.toDouble())) s.fail(key, "must hold finite numbers only");
        out.push_back(item.toDouble());
    }
    if (count >= 0 && static_cast<int>(out.size()) != count)
        s.fail(key, "must hold " + std::to_string(count) + " numbers");
    return out;
}

JsonSection section(const QJsonObject& parent, const QString& key) {
    if (!parent.value(key).isObject()) throw std::invalid_argument(key.toStdString() + ": missing (must be an object)");
    return JsonSection(parent, key);
}

QJsonObject networkToJson(const core::CorrectiveNet& net) {
    const core::NetWeights& w = net.weights();
    const core::NetNormalisation& n = net.normalisation();
    QJsonArray hidden;
    for (Eigen::Index r = 0; r < w.hidden.rows(); ++r) {
        const Eigen::Vector4d row = w.hidden.row(r).transpose();
        hidden.append(numbers(row.data(), 4));
    }
    return QJsonObject{
        {QStringLiteral("inputs"), QJsonArray{QStringLiteral("vx1_rad_per_s"), QStringLiteral("vz1_rad_per_s"),
                                              QStringLiteral("vx2_rad_per_s"), QStringLiteral("vz2_rad_per_s")}},
        {QStringLiteral("hidden_activation"), QStringLiteral("logistic sigmoid")},
        {QStringLiteral("output_activation"), QStringLiteral("linear")},
        {QStringLiteral("normalisation"),
         QJsonObject{{QStringLiteral("input_offset"), numbers(n.inputOffset.data(), 4)},
                     {QStringLiteral("input_scale"), numbers(n.inputScale.data(), 4)},
                     {QStringLiteral("output_offset_v"), n.outputOffset},
                     {QStringLiteral("output_scale_v"), n.outputScale}}},
        {QStringLiteral("hidden_weights"), hidden},
        {QStringLiteral("hidden_bias"), numbers(w.hiddenBias.data(), w.hiddenBias.size())},
        {QStringLiteral("output_weights"), numbers(w.output.data(), w.output.size())},
        {QStringLiteral("output_bias"), w.outputBias},
    };
}

QJsonObject recordToJson(const core::NetTrainingRecord& r) {
    return QJsonObject{
        {QStringLiteral("seed"), static_cast<qint64>(r.seed)},
        {QStringLiteral("training_samples"), r.trainingSamples},
        {QStringLiteral("validation_samples"), r.validationSamples},
        {QStringLiteral("epochs"), r.epochs},
        {QStringLiteral("best_epoch"), r.bestEpoch},
        {QStringLiteral("training_rms_v"), r.trainingRmsV},
        {QStringLiteral("validation_rms_v"), r.validationRmsV},
        {QStringLiteral("stop_reason"), QString::fromStdString(r.stopReason)},
        {QStringLiteral("retrainings"), r.retrainings},
        {QStringLiteral("training_loss"), numbers(r.trainingLoss)},
        {QStringLiteral("validation_loss"), numbers(r.validationLoss)},
    };
}

core::NetWeights readWeights(const JsonSection& s) {
    const QJsonValue rows = s.value(QStringLiteral("hidden_weights"));
    if (!rows.isArray() || rows.toArray().isEmpty() || rows.toArray().size() > 100)
        s.fail(QStringLiteral("hidden_weights"), "must be an array of 1 .. 100 rows of 4 numbers");
    const int h = static_cast<int>(rows.toArray().size());
    core::NetWeights w;
    w.hidden.resize(h, core::CorrectiveNet::kInputs);
    for (int r = 0; r < h; ++r) {
        const JsonSection row = JsonSection::of(QJsonObject{{QStringLiteral("row"), rows.toArray().at(r)}},
                                                s.name() + QStringLiteral(".hidden_weights[%1]").arg(r));
        const std::vector<double> v = readNumbers(row, QStringLiteral("row"), core::CorrectiveNet::kInputs);
        for (int c = 0; c < core::CorrectiveNet::kInputs; ++c)
            w.hidden(r, c) = v[static_cast<std::size_t>(c)];
    }
    const std::vector<double> b1 = readNumbers(s, QStringLiteral("hidden_bias"), h);
    const std::vector<double> w2 = readNumbers(s, QStringLiteral("output_weights"), h);
    w.hiddenBias = Eigen::Map<const Eigen::VectorXd>(b1.data(), h);
    w.output = Eigen::Map<const Eigen::VectorXd>(w2.data(), h);
    w.outputBias = s.required(QStringLiteral("output_bias"), -1e300, 1e300);
    return w;
}

core::NetNormalisation readNormalisation(const JsonSection& network) {
    const QJsonValue v = network.value(QStringLiteral("normalisation"));
    if (!v.isObject()) network.fail(QStringLiteral("normalisation"), "missing (must be an object)");
    const JsonSection s = JsonSection::of(v.toObject(), network.name() + QStringLiteral(".normalisation"));
    core::NetNormalisation n;
    const std::vector<double> offset = readNumbers(s, QStringLiteral("input_offset"), 4);
    const std::vector<double> scale = readNumbers(s, QStringLiteral("input_scale"), 4);
    std::copy(offset.begin(), offset.end(), n.inputOffset.begin());
    std::copy(scale.begin(), scale.end(), n.inputScale.begin());
    n.outputOffset = s.required(QStringLiteral("output_offset_v"), -1e300, 1e300);
    n.outputScale = s.required(QStringLiteral("output_scale_v"), 1e-300, 1e300);
    return n;
}

core::NetTrainingRecord readRecord(const JsonSection& s) {
    core::NetTrainingRecord r;
    r.seed = static_cast<unsigned long long>(s.number(QStringLiteral("seed"), 0.0, 0.0, 9007199254740991.0));
    r.trainingSamples = s.integer(QStringLiteral("training_samples"), 0, 0, 1000000);
    r.validationSamples = s.integer(QStringLiteral("validation_samples"), 0, 0, 1000000);
    r.epochs = s.integer(QStringLiteral("epochs"), 0, 0, 100000);
    r.bestEpoch = s.integer(QStringLiteral("best_epoch"), 0, 0, 100000);
    r.trainingRmsV = s.number(QStringLiteral("training_rms_v"), 0.0, 0.0, 1e6);
    r.validationRmsV = s.number(QStringLiteral("validation_rms_v"), 0.0, 0.0, 1e6);
    r.stopReason = s.text(QStringLiteral("stop_reason"), "");
    r.retrainings = s.integer(QStringLiteral("retrainings"), 0, 0, 1000000);
    if (s.has(QStringLiteral("training_loss"))) r.trainingLoss = readNumbers(s, QStringLiteral("training_loss"), -1);
    if (s.has(QStringLiteral("validation_loss")))
        r.validationLoss = readNumbers(s, QStringLiteral("validation_loss"), -1);
    return r;
}

core::PulseSettings readPulse(const JsonSection& s) {
    core::PulseSettings p;
    const std::string axis = s.text(QStringLiteral("axis"), "x");
    if (axis != "x" && axis != "z") s.fail(QStringLiteral("axis"), "must be \"x\" or \"z\"");
    p.axis = core::feedAxisFromString(axis.c_str());
    p.leadS = s.required(QStringLiteral("lead_s"), 0.0, 0.2);
    p.durationS = s.required(QStringLiteral("duration_s"), 0.001, 0.2);
    p.limitV = s.required(QStringLiteral("limit_v"), 0.01, core::kMaxPulseAmplitudeV);
    return p;
}

std::vector<core::NetSample> readSamples(const QJsonObject& json) {
    std::vector<core::NetSample> out;
    const QJsonValue v = json.value(QStringLiteral("samples"));
    if (v.isUndefined()) return out;
    if (!v.isArray()) throw std::invalid_argument("samples: must be an array");
    int i = 0;
    for (const QJsonValue& item : v.toArray()) {
        const JsonSection row =
            JsonSection::of(QJsonObject{{QStringLiteral("row"), item}}, QStringLiteral("samples[%1]").arg(i++));
        const std::vector<double> n = readNumbers(row, QStringLiteral("row"), 6);
        out.push_back({{n[0], n[1], n[2], n[3]}, n[4], n[5]});
    }
    return out;
}

}  // namespace

QJsonObject cornerNetToJson(const CornerNetFile& file) {
    QJsonArray samples;
    for (const core::NetSample& s : file.samples)
        samples.append(QJsonArray{s.speedsRadPerS[0], s.speedsRadPerS[1], s.speedsRadPerS[2], s.speedsRadPerS[3],
                                  s.amplitudeV, s.weight});
    return QJsonObject{
        {QStringLiteral("format"), kFormat},
        {QStringLiteral("version"), kVersion},
        {QStringLiteral("preset"), QString::fromStdString(file.preset)},
        {QStringLiteral("pulse"),
         QJsonObject{{QStringLiteral("axis"), QString::fromLatin1(core::toString(file.pulse.axis))},
                     {QStringLiteral("lead_s"), file.pulse.leadS},
                     {QStringLiteral("duration_s"), file.pulse.durationS},
                     {QStringLiteral("limit_v"), file.pulse.limitV}}},
        {QStringLiteral("network"), networkToJson(file.net)},
        {QStringLiteral("training"), recordToJson(file.net.record())},
        {QStringLiteral("samples"), samples},
    };
}

CornerNetFile cornerNetFromJson(const QJsonObject& json) {
    if (json.value(QStringLiteral("format")).toString() != kFormat)
        throw std::invalid_argument("format: not a TrueTurn corrective-pulse network (\"" + kFormat.toStdString() +
                                    "\" expected)");
    if (json.value(QStringLiteral("version")).toInt() != kVersion)
        throw std::invalid_argument("version: only version 1 is known");
    const JsonSection network = section(json, QStringLiteral("network"));
    const JsonSection training = section(json, QStringLiteral("training"));
    const JsonSection pulse = section(json, QStringLiteral("pulse"));
    return {core::CorrectiveNet(readWeights(network), readNormalisation(network), readRecord(training)),
            readPulse(pulse), json.value(QStringLiteral("preset")).toString().toStdString(), readSamples(json)};
}

QByteArray cornerNetToBytes(const CornerNetFile& file) {
    return QJsonDocument(cornerNetToJson(file)).toJson(QJsonDocument::Indented);
}

CornerNetFile cornerNetFromBytes(const QByteArray& bytes) {
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError)
        throw std::invalid_argument("not JSON: " + error.errorString().toStdString() + " at offset " +
                                    std::to_string(error.offset));
    if (!doc.isObject()) throw std::invalid_argument("not a JSON object");
    return cornerNetFromJson(doc.object());
}

}  // namespace tt::config

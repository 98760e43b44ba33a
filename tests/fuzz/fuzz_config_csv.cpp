// libFuzzer target: the CSV readers of the config layer (Qt Core) on arbitrary text: the profile
// CSV of fit-profile (x_mm,error_mm) when the first byte is even, the deformation experiment's CSV
// otherwise. Whatever is accepted must be finite and within the documented ranges.
#include <QByteArray>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "config/deformation_csv.h"
#include "config/profile_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const QByteArray text(reinterpret_cast<const char*>(data + 1), static_cast<qsizetype>(size - 1));
    try {
        if (data[0] % 2 == 0) {
            const tt::config::ProfileSamples s = tt::config::parseProfileCsv(text);
            if (s.xMm.size() == 0 || s.xMm.size() != s.errorMm.size()) __builtin_trap();
            if (!s.xMm.allFinite() || s.xMm.cwiseAbs().maxCoeff() > tt::config::kMaxAbsXMm) __builtin_trap();
            if (!s.errorMm.allFinite() || s.errorMm.cwiseAbs().maxCoeff() > tt::config::kMaxAbsErrorMm)
                __builtin_trap();
        } else {
            (void)tt::config::parseDeformationCsv(text);
        }
    } catch (const std::invalid_argument&) {
    }
    return 0;
}

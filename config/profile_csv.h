#pragma once

#include <Eigen/Core>
#include <QByteArray>

namespace tt::config {

/// Measured profile error samples read from a CSV file.
struct ProfileSamples {
    Eigen::VectorXd xMm;      ///< axial position, mm from the left end
    Eigen::VectorXd errorMm;  ///< diameter error (measured minus nominal), mm
};

/// The largest |x_mm| of a profile sample (a 100 m part), mm.
inline constexpr double kMaxAbsXMm = 1e5;
/// The largest |error_mm| of a profile sample (a diameter error of 100 mm is no longer a profile error), mm.
inline constexpr double kMaxAbsErrorMm = 100.0;

/// Parses a profile CSV: a header line `x_mm,error_mm`, then one `x,error` row per line (comma
/// separated, spaces around fields allowed, CRLF and a UTF-8 byte-order mark accepted, blank lines
/// and lines starting with '#' skipped). Throws std::invalid_argument with one line naming the
/// line number and the problem (missing header, missing or extra column, not a number, NaN/Inf, outside kMaxAbsXMm or
/// kMaxAbsErrorMm)
/// or that there are no data rows.
ProfileSamples parseProfileCsv(const QByteArray& text);

}  // namespace tt::config

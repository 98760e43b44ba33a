#pragma once

#include <Eigen/Core>
#include <QByteArray>

namespace tt::config {

/// Measured profile error samples read from a CSV file.
struct ProfileSamples {
    Eigen::VectorXd xMm;      ///< axial position, mm from the left end
    Eigen::VectorXd errorMm;  ///< diameter error (measured minus nominal), mm
};

/// Parses a profile CSV: a header line `x_mm,error_mm`, then one `x,error` row per line (comma
/// separated, spaces around fields allowed, CRLF and a UTF-8 byte-order mark accepted, blank lines
/// and lines starting with '#' skipped). Throws std::invalid_argument with one line naming the
/// line number and the problem (missing header, missing or extra column, not a number, NaN/Inf)
/// or that there are no data rows.
ProfileSamples parseProfileCsv(const QByteArray& text);

}  // namespace tt::config

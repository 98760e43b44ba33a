#pragma once

#include <QByteArray>
#include <QString>
#include <cstdint>
#include <optional>

#include "core/model/deformation_model.h"

namespace tt::config {

/// A force-deformation experiment as a CSV file: the rows and where they came from.
struct DeformationCsv {
    core::DeformationSamples samples;
    QString preset;                     ///< "# preset: NAME" (the set-up the bars were cut on), empty if absent
    std::optional<std::uint64_t> seed;  ///< "# seed: S" (the simulator's noise), if given
};

/// Parses the experiment CSV that `fit-deformation` reads: a header `a_mm,f_mm_rev,z_mm,y_um` (depth of
/// cut mm, feed mm/rev, axial position mm, deformation µm), then one row per measurement (comma
/// separated, spaces allowed, CRLF and a UTF-8 byte-order mark accepted, blank lines skipped). Lines
/// starting with '#' are comments; "# preset: NAME" and "# seed: S" among them are kept. At most
/// 1000000 rows. Throws std::invalid_argument naming the line and the problem (missing header, wrong
/// number of columns, not a number, NaN/Inf) or that there are no rows.
DeformationCsv parseDeformationCsv(const QByteArray& text);

/// The CSV text of `csv` (comment lines for the preset and seed when known, then the header and rows;
/// numbers with up to 10 significant digits).
QByteArray deformationCsvText(const DeformationCsv& csv);

}  // namespace tt::config

// merge_tiles's Job: the parts of one render (trace --tile K/N or --rows A:B, each a
// cube recording its rows, inputs and options: cube(5), Parts) checked against each
// other and joined into the whole cube, bit-identical to the cube rendered in one piece.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/report.hpp"
#include "image/image.hpp"

namespace sigchain::image {

// The rows a part holds: [begin, end) of `total` ("A:B of R", cube(5), Parts).
struct PartRows {
    long begin = 0, end = 0, total = 0;
};
// "A:B of R" with 0 <= A < B <= R; std::nullopt for anything else.
std::optional<PartRows> parse_part_rows(const std::string& text);
std::string part_rows_text(const PartRows& rows);

struct MergeJob {
    std::vector<std::string> part_paths;  // in any order
    std::string output_path;              // .img/.hdr (ENVI) or .tif (GeoTIFF)
    WriteOptions write_options;           // --co; the command recorded is the parts'
};

struct MergeReport {
    long rows = 0, columns = 0;
    int bands = 0;
};

// Checks the parts, then writes the whole cube atomically. DataError naming a part when
// it records no rows (not a part), another sigchain version, other inputs (their
// SHA-256) or other options than the first part, another size, or georeferencing (a
// geo-placed part's map grid is fitted to its own rows: render such scenes whole); and
// when the parts overlap or leave rows out. The whole cube records the parts' command
// without the part options, with -o OUTPUT last (cube(5), Parts). UsageError: no
// parts, an output that is a part, an unknown output extension.
MergeReport run_merge(const MergeJob& job, const Reporter& reporter);

}  // namespace sigchain::image

// What a part of a render records (cube(5), Parts): its rows of the whole image, a
// digest of every input file's bytes and the options, so that merge_tiles(1) can refuse
// parts that do not belong together.
#pragma once

#include <string>
#include <vector>

#include "image/image.hpp"
#include "trace/trace_job.hpp"

namespace sigchain::trace {

// The files a render reads: ADV SND SCENE MAT, the RADs, --tmp, the scene input
// options' files (--material-map, --landuse, --landuse-map), the files the .mat names
// (.ems, .ext, textures, BRDF tables; resolved as the materials resolve them) and the
// files an .odb scene places (resolved against the .odb). Missing names are skipped
// (the render itself reports them).
std::vector<std::string> input_files(const TraceJob& job);

// `options` with the part's items when [row_begin, row_end) is not every one of `rows`
// rows: "rows" ("A:B of R"), "tile" (K/N, with --tile), "inputs" (SHA-256 of
// input_files) and "options" (job.part_options). The whole image: `options` unchanged.
image::WriteOptions part_write_options(const TraceJob& job, long row_begin, long row_end,
                                       long rows);

}  // namespace sigchain::trace

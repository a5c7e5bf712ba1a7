// A raster written by GDAL that appears only when every byte is on disk as written.
#pragma once

#include <gdal_priv.h>

#include <memory>
#include <string>
#include <vector>

#include "core/output.hpp"

namespace sigchain::image {

// GDAL writes into a private temporary folder beside the target (TempDir); commit()
// closes the dataset, reads every band back and compares it with what was given to
// write_band, then renames the files into place (commit_moves). GDAL 3.6 drops some
// write errors (the ENVI driver's data on a full disk, a failed close), so the read-back
// is what proves the file whole; it costs one read of the file from the page cache.
// Any failure throws IoError "TARGET: write error: ...", and the target is untouched.
class GdalOutput {
public:
    // `target`: the name the data file takes; `driver`: "GTiff" or "ENVI".
    GdalOutput(const std::string& target, const char* driver, long columns, long rows,
               int bands, GDALDataType type, CSLConstList creation_options);
    GdalOutput(const GdalOutput&) = delete;
    GdalOutput& operator=(const GdalOutput&) = delete;
    ~GdalOutput();

    GDALDataset& dataset() { return *m_ds; }
    // Whether the creation options make the file lossy (COMPRESS=JPEG, lossy WEBP, LERC
    // with MAX_Z_ERROR, lossy JXL): then commit() checks that every band reads back,
    // not that it equals what was written.
    static bool lossy(CSLConstList creation_options);
    // Writes band `band` (1-based) from `data` (columns x rows samples of `type`), which
    // must stay valid until commit().
    void write_band(int band, GDALDataType type, const void* data);
    // Closes, verifies and renames. An ENVI header written beside the data file goes
    // last under the target's name with .hdr (commit_moves: it makes the pair readable).
    void commit();
    // Closes and verifies as commit() does, and returns the renames that commit it,
    // for commit_moves with other outputs' (one output made of several files).
    std::vector<Move> finish();

private:
    struct Written {
        int band;
        GDALDataType type;
        const void* data;
    };
    std::string m_target;
    TempDir m_folder;
    std::string m_temp;
    long m_columns, m_rows;
    std::unique_ptr<GDALDataset> m_ds;
    std::vector<std::string> m_files;
    std::vector<Written> m_written;
    bool m_exact = true;
};

}  // namespace sigchain::image

// A raster written by GDAL that appears only when every byte is on disk as written.
#pragma once

#include <gdal_priv.h>

#include <memory>
#include <string>
#include <vector>

#include "core/digest.hpp"
#include "core/output.hpp"
#include "geo/gdal_dataset.hpp"

namespace sigchain::image {

// GDAL writes into a private temporary folder beside the target (TempDir); commit()
// closes the dataset, reads every band back and compares it with what was written
// (its SHA-256, taken as the bytes went to GDAL), then renames the files into place
// (commit_moves). GDAL 3.6 drops some write errors (the ENVI driver's data on a full
// disk, a failed close), so the read-back is what proves the file whole; it costs one
// read of the file from the page cache, in row blocks of a few MiB (GDAL's block
// cache is emptied after each), so that it holds no second copy of the raster. Any
// failure throws IoError "TARGET: write error: ...", and the target is untouched.
// Not thread-safe; its calls may come from different threads one at a time.
class GdalOutput {
public:
    // `target`: the name the data file takes; `driver`: "GTiff" or "ENVI".
    GdalOutput(const std::string& target, const char* driver, long columns, long rows,
               int bands, GDALDataType type, CSLConstList creation_options);
    GdalOutput(const GdalOutput&) = delete;
    GdalOutput& operator=(const GdalOutput&) = delete;
    ~GdalOutput();

    GDALDataset& dataset() { return *m_ds; }
    const std::string& target() const { return m_target; }
    // A file name inside the private folder (scratch space removed with it).
    std::string scratch_file(const std::string& name) const { return m_folder.file(name); }
    // Whether the creation options make the file lossy (COMPRESS=JPEG, lossy WEBP, LERC
    // with MAX_Z_ERROR, lossy JXL): then commit() checks that every band reads back,
    // not that it equals what was written.
    static bool lossy(CSLConstList creation_options);
    // Writes band `band` (1-based) whole from `data` (columns x rows samples of `type`).
    void write_band(int band, GDALDataType type, const void* data);
    // Writes rows [first_row, first_row + rows) of band `band` from `data` (rows x
    // columns samples of `type`), a raw format's (ENVI's) as one transfer rather than
    // row by row through GDAL's cache. A band's rows come in order from row 0, each
    // once, in one type. logic_error otherwise.
    void write_rows(int band, long first_row, long rows, GDALDataType type, const void* data);
    // Hands the blocks of band `band` that GDAL's cache holds to the driver (in block
    // order) and drops them: what bounds the cache to the rows written since.
    void release(int band);
    // The height of the raster's blocks (strips or tiles), and whether its bands share
    // them (INTERLEAVE=PIXEL): a block is written once, complete, only when the rows
    // written between release() calls cover whole blocks (band by band, or every band
    // of them when shared), which keeps a compressed file's bytes those of one write.
    long block_rows();
    bool bands_share_blocks();
    // Closes, verifies and renames. An ENVI header written beside the data file goes
    // last under the target's name with .hdr (commit_moves: it makes the pair readable).
    void commit();
    // Closes and verifies as commit() does, and returns the renames that commit it,
    // for commit_moves with other outputs' (one output made of several files).
    std::vector<Move> finish();

private:
    struct Written {
        GDALDataType type = GDT_Unknown;
        long rows = 0;  // rows written so far, from row 0
        Sha256 digest;
    };
    void write(int band, long first_row, long rows, GDALDataType type, const void* data,
               bool direct);
    void verify(GDALDataset& back);
    std::string m_target;
    TempDir m_folder;
    std::string m_temp;
    long m_columns, m_rows;
    geo::GdalDataset m_ds;
    std::vector<std::string> m_files;
    std::vector<Written> m_written;  // per band, 0-based
    bool m_exact = true;
};

}  // namespace sigchain::image

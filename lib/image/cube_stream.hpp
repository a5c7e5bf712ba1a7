// A float32 cube written as its rows are made, top to bottom: what lets a renderer hold
// a few rows instead of the whole cube (trace(1), OUTPUT). The file is the one
// write_cube makes of the same image, byte for byte, and appears only when complete.
#pragma once

#include <memory>
#include <string>

#include "image/image.hpp"

namespace sigchain::image {

class GdalOutput;

// The cube goes into a private temporary folder beside `path` (as every GDAL output,
// gdal_output.hpp) and is renamed into place by commit(), with its geolocation arrays
// when the header's georeference carries some; destroyed uncommitted, it leaves nothing.
// ENVI rows go straight into the temporary .img (BSQ: each band's rows at their place).
// A GeoTIFF's bands lie one after the other in its file, each in blocks that a
// compressor writes as they fill, so its rows go first to a raw scratch file in the
// folder (as large as the cube), from which commit() writes the GeoTIFF band by band
// in whole blocks, as write_cube writes it from memory. Either way the memory held is
// GDAL's cache of a few MiB of rows, not the cube.
// Not thread-safe; its calls may come from different threads one at a time.
class CubeStream {
public:
    // `header`: the cube's rows, columns, channels and metadata (names, wavelengths,
    // units, sensor type, georeference), as write_cube takes them; its data is not read.
    // Throws what write_cube throws for the header (DataError, UsageError for --co on
    // a non-GeoTIFF, IoError when the temporary cannot be made).
    CubeStream(const std::string& path, const Image& header, CubeFormat format,
               const WriteOptions& options = {});
    ~CubeStream();
    CubeStream(const CubeStream&) = delete;
    CubeStream& operator=(const CubeStream&) = delete;

    // Writes rows [row, row + count) of `source` (an image of the cube's columns and
    // channels, of any number of rows) as the cube's next `count` rows. IoError
    // "PATH: write error: ..."; logic_error past the cube's last row.
    void append(const Image& source, long row, long count);
    long rows_written() const { return m_next; }
    // After the last row: verifies the file (GdalOutput) and renames it into place.
    // logic_error when rows are missing.
    void commit();

private:
    void spool(const Image& source, long row, long count);
    void unspool();
    Image m_header;  // the metadata alone
    std::unique_ptr<GdalOutput> m_out;
    std::string m_spool_path;  // GeoTIFF: the raw BSQ float32 scratch file
    int m_spool = -1;
    long m_next = 0;
};

}  // namespace sigchain::image

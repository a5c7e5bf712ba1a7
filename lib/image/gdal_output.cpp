// GdalOutput: GDAL's writes into a private folder, read back and renamed into place.
#include "image/gdal_output.hpp"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "core/error.hpp"
#include "core/text.hpp"
#include "geo/crs.hpp"

namespace sigchain::image {

namespace {

// GDAL's message, or the system's when GDAL gave none (a failed write at creation).
std::string failure(int saved_errno) {
    const char* m = CPLGetLastErrorMsg();
    if (m && *m) return m;
    return saved_errno != 0 ? std::strerror(saved_errno) : "unknown GDAL error";
}

// GDAL's raw drivers (ENVI) write and read a block of whole rows as one transfer with
// GDAL_ONE_BIG_READ set, instead of one cached block per row and band: the same bytes,
// a fraction of the system calls. Set for this thread while an object lives.
class DirectRawIo {
public:
    DirectRawIo() {
        if (const char* v = CPLGetThreadLocalConfigOption(kKey, nullptr)) m_previous = v;
        CPLSetThreadLocalConfigOption(kKey, "YES");
    }
    ~DirectRawIo() {
        CPLSetThreadLocalConfigOption(kKey, m_previous ? m_previous->c_str() : nullptr);
    }
    DirectRawIo(const DirectRawIo&) = delete;
    DirectRawIo& operator=(const DirectRawIo&) = delete;

private:
    static constexpr const char* kKey = "GDAL_ONE_BIG_READ";
    std::optional<std::string> m_previous;
};

// The read-back's row blocks: about this many bytes of every band whose blocks it holds.
constexpr double kReadBackBytes = 8.0 * 1024.0 * 1024.0;

// Rows per read-back block: whole blocks of `block` rows, about kReadBackBytes.
long read_back_rows(long block, double bytes_per_row) {
    const long n = std::max(1L, static_cast<long>(kReadBackBytes / std::max(1.0, bytes_per_row)));
    return std::max(block, n / block * block);
}

}  // namespace

bool GdalOutput::lossy(CSLConstList options) {
    const std::string compress = ascii_lower(CSLFetchNameValueDef(options, "COMPRESS", ""));
    const auto yes = [&](const char* key, const char* def) {
        const std::string v = ascii_lower(CSLFetchNameValueDef(options, key, def));
        return v == "yes" || v == "true" || v == "on" || v == "1";
    };
    if (compress == "jpeg") return true;
    if (compress == "webp") return !yes("WEBP_LOSSLESS", "NO");
    if (compress == "jxl") return !yes("JXL_LOSSLESS", "YES");
    if (compress.rfind("lerc", 0) == 0)
        return std::atof(CSLFetchNameValueDef(options, "MAX_Z_ERROR", "0")) > 0;
    return false;
}

GdalOutput::GdalOutput(const std::string& target, const char* driver_name, long columns,
                       long rows, int bands, GDALDataType type, CSLConstList creation_options)
    : m_target(target),
      m_folder(target),
      m_columns(columns),
      m_rows(rows),
      m_written(static_cast<std::size_t>(std::max(0, bands))),
      m_exact(!lossy(creation_options)) {
    geo::gdal_init();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name);
    if (!driver) throw IoError(target + ": GDAL has no " + driver_name + " driver");
    // GDAL opens its files itself: they go into a private folder beside the target.
    m_temp = m_folder.file(std::filesystem::path(target).filename().string());
    CPLErrorReset();
    errno = 0;
    m_ds.reset(driver->Create(m_temp.c_str(), static_cast<int>(columns), static_cast<int>(rows),
                              bands, type, creation_options));
    if (!m_ds) throw IoError(target + ": cannot create: " + failure(errno));
    if (char** list = m_ds->GetFileList()) {
        for (char** f = list; *f; ++f) m_files.emplace_back(*f);
        CSLDestroy(list);
    }
}

GdalOutput::~GdalOutput() = default;  // an uncommitted dataset goes with its folder

void GdalOutput::write_band(int band, GDALDataType type, const void* data) {
    write(band, 0, m_rows, type, data, false);
}

void GdalOutput::write_rows(int band, long first_row, long rows, GDALDataType type,
                            const void* data) {
    write(band, first_row, rows, type, data, true);
}

void GdalOutput::write(int band, long first_row, long rows, GDALDataType type, const void* data,
                       bool direct) {
    Written& w = m_written.at(static_cast<std::size_t>(band - 1));
    if (first_row != w.rows || rows < 1 || first_row + rows > m_rows ||
        (w.rows > 0 && w.type != type))
        throw std::logic_error("GdalOutput::write_rows: band " + std::to_string(band) +
                               " rows out of order");
    std::optional<DirectRawIo> raw;
    if (direct) raw.emplace();
    CPLErrorReset();
    errno = 0;
    if (m_ds->GetRasterBand(band)->RasterIO(GF_Write, 0, static_cast<int>(first_row),
                                            static_cast<int>(m_columns), static_cast<int>(rows),
                                            const_cast<void*>(data), static_cast<int>(m_columns),
                                            static_cast<int>(rows), type, 0, 0,
                                            nullptr) != CE_None ||
        CPLGetLastErrorType() >= CE_Failure)
        throw IoError(m_target + ": write error: " + failure(errno));
    w.type = type;
    w.rows += rows;
    w.digest.add(data, static_cast<std::size_t>(GDALGetDataTypeSizeBytes(type)) *
                           static_cast<std::size_t>(m_columns) * static_cast<std::size_t>(rows));
}

void GdalOutput::release(int band) {
    CPLErrorReset();
    errno = 0;
    // libtiff reports some failures (a directory it could not write) through GDAL's
    // error handler alone: an error raised here is a write error too.
    if (m_ds->GetRasterBand(band)->FlushCache(false) != CE_None ||
        CPLGetLastErrorType() >= CE_Failure)
        throw IoError(m_target + ": write error: " + failure(errno));
}

long GdalOutput::block_rows() {
    int columns = 0, rows = 0;
    m_ds->GetRasterBand(1)->GetBlockSize(&columns, &rows);
    return std::max(1, rows);
}

bool GdalOutput::bands_share_blocks() {
    const char* interleave = m_ds->GetMetadataItem("INTERLEAVE", "IMAGE_STRUCTURE");
    return m_ds->GetRasterCount() > 1 && interleave && ascii_lower(interleave) == "pixel";
}

// Reads every written band back in row blocks (each block's GDAL cache dropped after
// it) and, for a lossless file, compares its SHA-256 with the one taken as it was written.
void GdalOutput::verify(GDALDataset& back) {
    int block_columns = 0, block = 0;
    back.GetRasterBand(1)->GetBlockSize(&block_columns, &block);
    const char* interleave = back.GetMetadataItem("INTERLEAVE", "IMAGE_STRUCTURE");
    const bool shared = interleave && ascii_lower(interleave) == "pixel";
    const double row_bytes = 8.0 * static_cast<double>(m_columns) *
                             (shared ? static_cast<double>(m_written.size()) : 1.0);
    const long step = read_back_rows(std::max(1, block), row_bytes);
    std::vector<Sha256> read(m_written.size());
    std::vector<unsigned char> buffer;
    const DirectRawIo direct;
    for (long first = 0; first < m_rows; first += step) {
        const long n = std::min(step, m_rows - first);
        for (std::size_t b = 0; b < m_written.size(); ++b) {
            const Written& w = m_written[b];
            if (w.rows == 0) continue;
            GDALRasterBand* band = back.GetRasterBand(static_cast<int>(b) + 1);
            buffer.resize(static_cast<std::size_t>(GDALGetDataTypeSizeBytes(w.type)) *
                          static_cast<std::size_t>(m_columns) * static_cast<std::size_t>(n));
            if (band->RasterIO(GF_Read, 0, static_cast<int>(first), static_cast<int>(m_columns),
                               static_cast<int>(n), buffer.data(), static_cast<int>(m_columns),
                               static_cast<int>(n), w.type, 0, 0, nullptr) != CE_None)
                throw IoError(m_target + ": write error: band " + std::to_string(b + 1) +
                              " did not reach the disk as written (a full disk?)");
            read[b].add(buffer.data(), buffer.size());
            band->FlushCache(false);
        }
    }
    if (!m_exact) return;
    for (std::size_t b = 0; b < m_written.size(); ++b)
        if (m_written[b].rows > 0 && read[b].hex() != m_written[b].digest.hex())
            throw IoError(m_target + ": write error: band " + std::to_string(b + 1) +
                          " did not reach the disk as written (a full disk?)");
}

void GdalOutput::commit() { commit_moves(finish()); }

std::vector<Move> GdalOutput::finish() {
    for (std::size_t b = 0; b < m_written.size(); ++b)
        if (m_written[b].rows != 0 && m_written[b].rows != m_rows)
            throw std::logic_error("GdalOutput::finish: band " + std::to_string(b + 1) +
                                   " has rows missing");
    // What was set in the ENVI header domain: GDAL 3.6 writes a header past its first
    // 4 KiB with no error when the disk is full, so the header is read back too.
    std::vector<std::pair<std::string, std::string>> header;
    if (char** items = m_ds->GetMetadata("ENVI"))
        for (char** i = items; *i; ++i) {
            char* key = nullptr;
            const char* value = CPLParseNameValue(*i, &key);
            if (key && value) header.emplace_back(key, value);
            CPLFree(key);
        }
    const int gcps = m_ds->GetGCPCount();
    CPLErrorReset();
    errno = 0;
    m_ds.reset();  // GDALClose: flushes the data and writes an ENVI header
    if (CPLGetLastErrorType() >= CE_Failure)
        throw IoError(m_target + ": write error: " + failure(errno));
    // Read back what was written: the bytes on disk, or the reason they are not.
    geo::GdalDataset back = geo::open_dataset(m_temp);
    if (!back) throw IoError(m_target + ": write error: the file written cannot be read back: " +
                             failure(errno));
    verify(*back);
    const auto squeeze = [](std::string s) {
        s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }),
                s.end());
        return s;
    };
    for (const auto& [key, value] : header) {
        const char* read = back->GetMetadataItem(key.c_str(), "ENVI");
        if (!read || squeeze(read) != squeeze(value))
            throw IoError(m_target + ": write error: the header's " + key +
                          " did not reach the disk as written (a full disk?)");
    }
    if (gcps > 0 && back->GetGCPCount() != gcps)
        throw IoError(m_target + ": write error: the ground control points did not reach the "
                                 "disk as written (a full disk?)");
    back.reset();
    std::vector<Move> moves{{m_temp, m_target}};
    for (const std::string& f : m_files)
        if (f != m_temp && file_extension(f) == "hdr")
            moves.push_back(
                {f, std::filesystem::path(m_target).replace_extension(".hdr").string()});
    return moves;
}

}  // namespace sigchain::image

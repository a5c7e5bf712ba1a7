// GdalOutput: GDAL's writes into a private folder, read back and renamed into place.
#include "image/gdal_output.hpp"

#include <cpl_error.h>
#include <cpl_string.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

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
    CPLErrorReset();
    errno = 0;
    if (m_ds->GetRasterBand(band)->RasterIO(GF_Write, 0, 0, static_cast<int>(m_columns),
                                            static_cast<int>(m_rows), const_cast<void*>(data),
                                            static_cast<int>(m_columns),
                                            static_cast<int>(m_rows), type, 0, 0,
                                            nullptr) != CE_None)
        throw IoError(m_target + ": write error: " + failure(errno));
    m_written.push_back({band, type, data});
}

void GdalOutput::commit() { commit_moves(finish()); }

std::vector<Move> GdalOutput::finish() {
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
    std::unique_ptr<GDALDataset> back(static_cast<GDALDataset*>(GDALOpenEx(
        m_temp.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    if (!back) throw IoError(m_target + ": write error: the file written cannot be read back: " +
                             failure(errno));
    std::vector<unsigned char> buffer;
    for (const Written& w : m_written) {
        const std::size_t bytes = static_cast<std::size_t>(GDALGetDataTypeSizeBytes(w.type)) *
                                  static_cast<std::size_t>(m_columns) *
                                  static_cast<std::size_t>(m_rows);
        buffer.assign(bytes, 0);
        if (back->GetRasterBand(w.band)->RasterIO(GF_Read, 0, 0, static_cast<int>(m_columns),
                                                  static_cast<int>(m_rows), buffer.data(),
                                                  static_cast<int>(m_columns),
                                                  static_cast<int>(m_rows), w.type, 0, 0,
                                                  nullptr) != CE_None ||
            (m_exact && std::memcmp(buffer.data(), w.data, bytes) != 0))
            throw IoError(m_target + ": write error: band " + std::to_string(w.band) +
                          " did not reach the disk as written (a full disk?)");
    }
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

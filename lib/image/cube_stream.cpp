// CubeStream: a cube's rows into GDAL as they come (ENVI) or through a raw scratch file
// (GeoTIFF), committed as write_cube commits a whole image.
#include "image/cube_stream.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/error.hpp"
#include "image/gdal_output.hpp"
#include "image/gdal_write.hpp"

namespace sigchain::image {

namespace {

// The GeoTIFF's rows are copied from the scratch file in whole blocks of about this
// many bytes (of one band, or of every band when they share blocks).
constexpr double kCopyBytes = 4.0 * 1024.0 * 1024.0;

// `image` without its data.
Image metadata_of(const Image& image) {
    Image h;
    h.rows = image.rows;
    h.columns = image.columns;
    h.channels = image.channels;
    h.wavelength_um = image.wavelength_um;
    h.fwhm_um = image.fwhm_um;
    h.channel_names = image.channel_names;
    h.units = image.units;
    h.sensor_type = image.sensor_type;
    h.scale = image.scale;
    h.offset = image.offset;
    h.scaled_units = image.scaled_units;
    h.georef = image.georef;
    return h;
}

// Row r of channel c of `image`, and the rows after it in that channel.
const float* row_of(const Image& image, int c, long r) {
    return image.data.data() +
           (static_cast<std::size_t>(c) * static_cast<std::size_t>(image.rows) +
            static_cast<std::size_t>(r)) *
               static_cast<std::size_t>(image.columns);
}

// pwrite or pread of `bytes` at `offset` whole (short transfers and EINTR resumed).
template <class Call>
bool transfer_all(Call call, char* data, std::size_t bytes, off_t offset) {
    while (bytes > 0) {
        const ssize_t n = call(data, bytes, offset);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = EIO;
            return false;
        }
        data += n, bytes -= static_cast<std::size_t>(n), offset += n;
    }
    return true;
}

}  // namespace

CubeStream::CubeStream(const std::string& path, const Image& header, CubeFormat format,
                       const WriteOptions& options)
    : m_header(metadata_of(header)) {
    m_out = detail::create_gdal(path, m_header, GDT_Float32, format, options);
    if (format != CubeFormat::GeoTiff) return;
    m_spool_path = m_out->scratch_file("rows.f32");
    m_spool = ::open(m_spool_path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (m_spool < 0)
        throw IoError(m_out->target() + ": cannot create " + m_spool_path + ": " +
                      std::strerror(errno));
}

CubeStream::~CubeStream() {
    if (m_spool >= 0) ::close(m_spool);
}

void CubeStream::append(const Image& source, long row, long count) {
    if (source.columns != m_header.columns || source.channels != m_header.channels || row < 0 ||
        count < 0 || row + count > source.rows || m_next + count > m_header.rows)
        throw std::logic_error("CubeStream::append: rows outside the cube");
    if (count == 0) return;
    if (m_spool >= 0) {
        spool(source, row, count);
    } else {
        for (int c = 0; c < m_header.channels; ++c) {
            m_out->write_rows(c + 1, m_next, count, GDT_Float32, row_of(source, c, row));
            m_out->release(c + 1);
        }
    }
    m_next += count;
}

// Channel c's rows at their place in the scratch file: BSQ, as the GeoTIFF's bands lie.
void CubeStream::spool(const Image& source, long row, long count) {
    const std::size_t row_bytes = 4 * static_cast<std::size_t>(m_header.columns);
    for (int c = 0; c < m_header.channels; ++c) {
        const off_t offset = static_cast<off_t>(
            (static_cast<std::size_t>(c) * static_cast<std::size_t>(m_header.rows) +
             static_cast<std::size_t>(m_next)) *
            row_bytes);
        const auto write = [this](char* p, std::size_t n, off_t at) {
            return ::pwrite(m_spool, p, n, at);
        };
        char* data = const_cast<char*>(reinterpret_cast<const char*>(row_of(source, c, row)));
        if (!transfer_all(write, data, row_bytes * static_cast<std::size_t>(count), offset))
            throw IoError(m_out->target() + ": write error: " + std::strerror(errno));
    }
}

// The scratch file into the GeoTIFF in whole blocks: band after band (each band's
// blocks written in order, as from one band written whole), or row blocks of every
// band when the bands share blocks (INTERLEAVE=PIXEL); then the scratch file goes.
void CubeStream::unspool() {
    const long rows = m_header.rows, bands = m_header.channels;
    const bool shared = m_out->bands_share_blocks();
    const long block = m_out->block_rows();
    const double row_bytes = 4.0 * static_cast<double>(m_header.columns) *
                             (shared ? static_cast<double>(bands) : 1.0);
    const long step = std::max(block, static_cast<long>(kCopyBytes / row_bytes) / block * block);
    const std::size_t plane_row = 4 * static_cast<std::size_t>(m_header.columns);
    std::vector<float> buffer;
    const auto copy = [&](long band, long first, long n) {
        buffer.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(m_header.columns));
        const off_t offset = static_cast<off_t>(
            (static_cast<std::size_t>(band) * static_cast<std::size_t>(rows) +
             static_cast<std::size_t>(first)) *
            plane_row);
        const auto read = [this](char* p, std::size_t len, off_t at) {
            return ::pread(m_spool, p, len, at);
        };
        if (!transfer_all(read, reinterpret_cast<char*>(buffer.data()),
                          plane_row * static_cast<std::size_t>(n), offset))
            throw IoError(m_out->target() + ": write error: the rows written cannot be read "
                                            "back: " + std::strerror(errno));
        m_out->write_rows(static_cast<int>(band) + 1, first, n, GDT_Float32, buffer.data());
    };
    for (long first = 0; shared && first < rows; first += step) {
        const long n = std::min(step, rows - first);
        for (long b = 0; b < bands; ++b) copy(b, first, n);
        for (long b = 0; b < bands; ++b) m_out->release(static_cast<int>(b) + 1);
    }
    for (long b = 0; !shared && b < bands; ++b)
        for (long first = 0; first < rows; first += step) {
            copy(b, first, std::min(step, rows - first));
            m_out->release(static_cast<int>(b) + 1);
        }
    ::close(m_spool);
    m_spool = -1;
    ::unlink(m_spool_path.c_str());
}

void CubeStream::commit() {
    if (m_next != m_header.rows)
        throw std::logic_error("CubeStream::commit: " + std::to_string(m_header.rows - m_next) +
                               " rows missing");
    if (m_spool >= 0) unspool();
    detail::commit_gdal(*m_out, m_header);
}

}  // namespace sigchain::image

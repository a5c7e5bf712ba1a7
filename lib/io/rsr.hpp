// Relative spectral response tables (man rsr(5)): a wavelength column in nm and one response
// column per band, such as data/spectra/landsat*_rsr.txt.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

struct RsrTable {
    std::vector<std::string> header;       // the `#` lines before the rows, without '#'
    std::string wavelength_column;         // "wavelength_nm"
    std::vector<std::string> band_names;   // the other columns' names, "B1", "B10"
    std::vector<double> wavelength_nm;     // strictly increasing
    // response[b][i]: band b at wavelength_nm[i], unitless, as given (small negative
    // values of a measured response are kept; users treat them as 0).
    std::vector<std::vector<double>> response;
    std::vector<int> row_lines;  // the line of each row
    bool operator==(const RsrTable&) const = default;
};

// `#` lines, the last of which names the columns ("# wavelength_nm B1 B2 ..."), then rows of
// as many numbers; blank lines are ignored, a `#` after the first row starts a comment.
// DataError "FILE:LINE: expected ..." for a missing column line, a first column not named
// wavelength_nm, a row with the wrong number of fields or a non-number, wavelengths not
// strictly increasing, fewer than 2 rows.
RsrTable parse_rsr(const TextInput& in);
void write_rsr(std::ostream& out, const RsrTable& table);
inline RsrTable read_rsr_file(const std::string& path) {
    return parse_rsr(TextInput::from_file(path));
}
// The column of band `name` ("4" matches "B4" and "4"), or -1.
int rsr_column(const RsrTable& table, const std::string& name);
FormatHandler rsr_format();

}  // namespace sigchain::io

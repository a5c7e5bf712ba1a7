// Fortran fixed-column fields (Iw, Fw.d, Ew.d, Aw) read and written as LOWTRAN 7 does.
//
// Reading follows FORTRAN 77 list-free formatted input with BLANK='NULL' (the default
// for a file opened without BLANK=, as LOWTRAN opens its card deck):
//   - a line shorter than the card is padded with blanks;
//   - an all-blank field is 0;
//   - leading and trailing blanks in a field are ignored; a blank between two
//     characters of a number is rejected here (Fortran would silently drop it, which
//     hides typing errors such as "2 3.000");
//   - an F or E field without a decimal point has an implied decimal point d digits
//     from the right of its digits (F10.3 "218" is 0.218, "218E2" is 21.8);
//   - an exponent is written E, D (either case) or just a sign ("0.998+03").
// Writing gives what a Fortran WRITE with the same edit descriptor gives, with E fields
// as 0.dddE+xx ("0.998E+03"). Nothing here is locale-dependent.
#pragma once

#include <string>
#include <string_view>

#include "core/error.hpp"

namespace sigchain::io::fortran {

// One card (line) of a fixed-column deck. Columns are 1-based as in Fortran. Every
// error names the card, the field and its columns: "CARD 2 VIS (columns 31-40): ...".
// The card's text must outlive the Card (it is a view).
class Card {
public:
    // Rejects control characters (a tab would shift every later column).
    Card(std::string_view text, SourceLocation where, std::string name);

    // Iw: an optionally signed integer; all blank is 0.
    long integer(int column, int width, std::string_view field) const;
    // Fw.d or Ew.d (read identically): a finite real; all blank is 0.
    double real(int column, int width, int decimals, std::string_view field) const;
    // Aw: the characters in the columns, padded with blanks to `width`.
    std::string characters(int column, int width) const;
    // Fails unless every column from `column` on is blank (nothing beyond the card).
    void require_blank_from(int column) const;
    bool blank() const;

    const SourceLocation& where() const { return m_where; }
    const std::string& name() const { return m_name; }
    // Throws a DataError "NAME FIELD (columns A-B): MESSAGE" at this card's line.
    [[noreturn]] void fail(std::string_view field, int column, int width,
                           const std::string& message) const;

private:
    std::string_view slice(int column, int width) const;
    std::string_view m_text;
    SourceLocation m_where;
    std::string m_name;
};

// Iw: right-aligned; throws sigchain::Error if the value needs more than `width` columns.
std::string format_integer(long value, int width);
// Fw.d ("%w.df"); a value too large for the field is written in E form with as many
// digits as fit (which Fortran F input accepts); throws sigchain::Error if even that
// does not fit. A value that rounds to zero is written as 0 (never "-0.000").
std::string format_fixed(double value, int width, int decimals);
// Ew.d as Fortran writes it: 0.ddd then E+xx (exponents beyond 99: +xxx without the E).
std::string format_exponent(double value, int width, int decimals);

}  // namespace sigchain::io::fortran

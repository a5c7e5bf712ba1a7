// A scene's date, time and place: a plain record, header only, which io (io::scene_site
// makes one from an .snd) and the solar position (solar_position.hpp) share, so that
// the format readers need none of the sun's physics.
#pragma once

namespace sigchain::geo {

// The scene's date, time and place as the scene node (.snd) gives them; io::scene_site
// makes one from an io::Snd.
struct SceneSite {
    int year = 2000;                // the scene's date (its local date)
    int month = 1;                  // 1-12
    int day = 1;                    // 1-31
    double time_gmt_hours = 0;      // decimal hours GMT (UT), [0, 24)
    double gmt_offset_hours = 0;    // GMT = local time + offset (5 for US Eastern standard)
    double latitude_deg = 0;        // of the target, north positive
    double longitude_east_deg = 0;  // of the target, east positive, (-180, 360)
};

}  // namespace sigchain::geo

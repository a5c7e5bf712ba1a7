// Radiosonde soundings for the card deck: missing dew points filled, levels as LOWTRAN 7
// CARD 2C1 layers (see radiosonde.hpp).
#include "control7/radiosonde.hpp"

#include <algorithm>
#include <string>

#include "core/text.hpp"

namespace sigchain::control7 {

io::Rsd fill_missing_dew_points(const io::Rsd& rsd, const SourceLocation& where) {
    io::Rsd out = rsd;
    std::vector<std::size_t> valid;
    for (std::size_t i = 0; i < out.levels.size(); ++i) {
        const auto& l = out.levels[i];
        if (!l.temperature_c)
            throw DataError(where, "level " + std::to_string(i + 1) + " (" +
                                       format_number(l.altitude_km) +
                                       " km) has no temperature (-999)");
        if (l.dew_point_c) valid.push_back(i);
    }
    if (valid.empty()) throw DataError(where, "no level has a dew point (all -999)");
    auto depression = [&](std::size_t i) {
        return *out.levels[i].temperature_c - *out.levels[i].dew_point_c;
    };
    for (std::size_t i = 0; i < out.levels.size(); ++i) {
        auto& l = out.levels[i];
        if (l.dew_point_c) continue;
        double d;
        if (i > valid.back()) {
            d = depression(valid.back());  // White (1996), section 4.2.3.4: keep the last depression
        } else if (i < valid.front()) {
            d = depression(valid.front());
        } else {
            auto hi = *std::upper_bound(valid.begin(), valid.end(), i);
            auto lo = *(std::upper_bound(valid.begin(), valid.end(), i) - 1);
            double t = (l.altitude_km - out.levels[lo].altitude_km) /
                       (out.levels[hi].altitude_km - out.levels[lo].altitude_km);
            d = depression(lo) + t * (depression(hi) - depression(lo));
        }
        l.dew_point_c = *l.temperature_c - d;
    }
    return out;
}

io::CdkProfile radiosonde_profile(const io::Rsd& rsd, int levels, const std::string& title) {
    io::CdkProfile p;
    p.title = title;
    for (int i = 0; i < levels; ++i) {
        const io::RsdLevel& l = rsd.levels.at(static_cast<std::size_t>(i));
        io::CdkLayer layer;
        layer.altitude_km = l.altitude_km;
        layer.pressure = l.pressure_mb;
        layer.temperature = l.temperature_c.value();
        layer.wmol = {l.dew_point_c.value(), 0, 0};
        layer.jchar = "ABG";  // mb, deg C, dew point in deg C (fig. 4.31)
        p.layers.push_back(layer);
    }
    return p;
}

}  // namespace sigchain::control7

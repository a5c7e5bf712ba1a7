// What the atmospheric column (column_model.hpp) is made from besides the deck's run.
// build_radiance's options (lib/atmos_table/radiance_options.hpp) extend these.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace sigchain::atmos {

struct ColumnOptions {
    std::string data_dir;            // reference data (core/data_dir.hpp)
    std::string snd_path = "<snd>";  // named in messages about the scene node
    double top_km = 100;             // top of the modelled atmosphere
    // The only wavenumbers (cm-1) the column is asked about (build_radiance: the .snd's
    // samples): gas tables that do not reach them are not read (GasTables::load).
    // Unset: every table.
    std::optional<std::pair<double, double>> wavenumbers_cm1;
};

}  // namespace sigchain::atmos

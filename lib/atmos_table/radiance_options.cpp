// build_radiance's options (see radiance_options.hpp).
#include "atmos_table/radiance_options.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/text.hpp"

namespace sigchain::atmos_table {

void check_radiance_options(const RadianceOptions& o) {
    if (o.streams != kAutoStreams && (o.streams < 4 || o.streams % 2 != 0 || o.streams > 64))
        throw UsageError("streams must be even, 4 to 64; found " + format_number(o.streams));
    if (!(o.stream_tolerance > 0 && o.stream_tolerance <= 1))
        throw UsageError("the stream tolerance must be > 0 and <= 1; found " +
                         format_number(o.stream_tolerance));
    auto divides = [](double whole, double step) {
        const double n = whole / step;
        return step > 0 && n >= 1 && std::abs(n - std::round(n)) < 1e-9;
    };
    if (!divides(90, o.sky_zenith_step_deg))
        throw UsageError("the sky zenith step must divide 90 deg; found " +
                         format_number(o.sky_zenith_step_deg));
    if (!divides(360, o.sky_azimuth_step_deg))
        throw UsageError("the sky azimuth step must divide 360 deg; found " +
                         format_number(o.sky_azimuth_step_deg));
    if (!divides(360, o.upwelled_azimuth_step_deg))
        throw UsageError("the upwelled azimuth step must divide 360 deg; found " +
                         format_number(o.upwelled_azimuth_step_deg));
    if (o.max_gas_terms < 1 || o.max_gas_terms > 16)
        throw UsageError("gas terms must be 1 to 16; found " + format_number(o.max_gas_terms));
    if (o.sky_subsamples < 1 || o.sky_subsamples > 8)
        throw UsageError("sky subsamples must be 1 to 8; found " + format_number(o.sky_subsamples));
}

}  // namespace sigchain::atmos_table

// Writing the .cdk LOWTRAN 7 card deck in LOWTRAN 7's columns (man cdk(5)).
#include <string>

#include "io/cdk.hpp"
#include "io/fortran_columns.hpp"

namespace sigchain::io {

namespace {

using fortran::format_exponent;
using fortran::format_fixed;
using fortran::format_integer;

std::string i5(long v) { return format_integer(v, 5); }
std::string f10(double v) { return format_fixed(v, 10, 3); }
std::string e10(double v) { return format_exponent(v, 10, 3); }

// One card per line, without trailing blanks.
void card(std::ostream& out, std::string text) {
    text.erase(text.find_last_not_of(' ') + 1);
    out << text << '\n';
}

void write_card1(std::ostream& out, const CdkCard1& k) {
    std::string s = i5(k.model) + i5(k.itype) + i5(k.iemsct) + i5(k.imult);
    for (int m : k.m) s += i5(m);
    s += i5(k.mdef) + i5(k.im) + i5(k.noprt) + format_fixed(k.boundary_temperature_k, 8, 3) +
         format_fixed(k.surface_albedo, 7, 2);
    card(out, s);
}

void write_card2(std::ostream& out, const CdkCard2& k) {
    card(out, i5(k.ihaze) + i5(k.iseasn) + i5(k.ivulcn) + i5(k.icstl) + i5(k.icld) + i5(k.ivsa) +
                  f10(k.visibility_km) + f10(k.wind_speed_m_s) + f10(k.wind_speed_24h_m_s) +
                  f10(k.rain_rate_mm_h) + f10(k.ground_altitude_km));
}

void write_layer(std::ostream& out, const CdkLayer& l) {
    card(out, f10(l.altitude_km) + e10(l.pressure) + e10(l.temperature) + e10(l.wmol[0]) +
                  e10(l.wmol[1]) + e10(l.wmol[2]) + l.jchar.substr(0, 15));
    if (l.wmol_4_12) {
        std::string s;
        for (int i = 0; i < 8; ++i) s += e10((*l.wmol_4_12)[i]);
        card(out, s);
        card(out, e10((*l.wmol_4_12)[8]));
    }
    if (l.aerosol) {
        const CdkLayerAerosol& a = *l.aerosol;
        card(out, std::string(10, ' ') + f10(a.extinction_km1) + f10(a.liquid_water_g_m3) +
                      f10(a.rain_rate_mm_h) + i5(a.iha1) + i5(a.icld1) + i5(a.ivul1) + i5(a.isea1) +
                      i5(a.ichr));
    }
}

void write_profile(std::ostream& out, const CdkProfile& p) {
    if (p.layers.empty() || p.layers.size() > static_cast<std::size_t>(kCdkMaxLayers))
        throw Error("a CARD 2C profile needs 1 to 34 layers, not " +
                    std::to_string(p.layers.size()));
    card(out,
         i5(static_cast<long>(p.layers.size())) + i5(p.ird1) + i5(p.ird2) + p.title.substr(0, 72));
    for (const auto& l : p.layers) {
        if (l.wmol_4_12.has_value() != (p.ird1 == 1) || l.aerosol.has_value() != (p.ird2 == 1))
            throw Error("a CARD 2C1 layer's CARD 2C2/2C3 do not match IRD1/IRD2");
        write_layer(out, l);
    }
}

void write_geometry(std::ostream& out, const CdkGeometry& g, const CdkCard1& card1) {
    if (card1.iemsct == 3) {
        card(out, f10(g.h1_km) + f10(g.h2_km) + f10(g.zenith_angle_deg) + i5(g.iday) +
                      std::string(5, ' ') + f10(g.earth_radius_km) + i5(g.isourc) +
                      f10(g.moon_phase_angle_deg));
        return;
    }
    card(out, f10(g.h1_km) + f10(g.h2_km) + f10(g.zenith_angle_deg) + f10(g.range_km) +
                  f10(g.earth_center_angle_deg) + f10(g.earth_radius_km) + i5(g.len));
    if (card1.iemsct != 2) return;
    card(out, i5(g.iparm) + i5(g.iph) + i5(g.iday) + i5(g.isourc));
    card(out, f10(g.parm[0]) + f10(g.parm[1]) + f10(g.parm[2]) + f10(g.parm[3]) + f10(g.time_h) +
                  f10(g.path_azimuth_deg) + f10(g.moon_phase_angle_deg) + f10(g.asymmetry_g));
    if (g.iph != 1) return;
    card(out, i5(static_cast<long>(g.phase_function.size())));
    for (const auto& p : g.phase_function) {
        std::string s = e10(p.angle_deg);
        for (double f : p.phase_function_sr1) s += e10(f);
        card(out, s);
    }
}

void write_card4(std::ostream& out, const CdkSpectral& s) {
    card(out, f10(s.v1_cm1) + f10(s.v2_cm1) + f10(s.dv_cm1));
}

void write_full(std::ostream& out, const CdkRun& run) {
    write_card1(out, run.card1);
    write_card2(out, run.card2);
    if (run.card2.icld >= 18) {
        if (!run.cirrus) throw Error("ICLD 18-20 needs CARD 2A (cirrus)");
        card(out, f10(run.cirrus->thickness_km) + f10(run.cirrus->base_altitude_km) +
                      f10(run.cirrus->extinction_km1) + format_integer(run.cirrus->iseed, 10));
    }
    if (run.card2.ivsa == 1) {
        if (!run.vsa) throw Error("IVSA 1 needs CARD 2B");
        card(out, f10(run.vsa->cloud_ceiling_km) + f10(run.vsa->cloud_thickness_km) +
                      f10(run.vsa->inversion_km));
    }
    bool user_profile = run.card1.model == 0 || run.card1.model == 7;
    if (user_profile && run.card1.im == 1) {
        if (!run.profile) throw Error("MODEL 0/7 with IM 1 needs a CARD 2C profile");
        write_profile(out, *run.profile);
    }
    if (run.card2.ihaze == 7 || run.card2.icld == 11) {
        if (!run.user_optics) throw Error("IHAZE 7 or ICLD 11 needs CARD 2D");
        write_cdk_card2d(out, *run.user_optics);
    }
    write_geometry(out, run.geometry, run.card1);
    write_card4(out, run.spectral);
}

}  // namespace

void write_cdk(std::ostream& out, const Cdk& cdk) {
    for (const auto& run : cdk.runs) {
        switch (run.kind) {
            case CdkRunKind::Full:
                write_full(out, run);
                break;
            case CdkRunKind::Geometry:
                write_geometry(out, run.geometry, run.card1);
                break;
            case CdkRunKind::Spectral:
                write_card4(out, run.spectral);
                break;
        }
        card(out, i5(run.irpt));
    }
}

}  // namespace sigchain::io

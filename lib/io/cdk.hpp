// .cdk LOWTRAN 7 card deck (White (1996), fig. 4.30-4.31, section 4.2.3.5; man cdk(5)): the
// atmosphere, path, sun geometry and spectral range of one or more LOWTRAN runs.
//
// The deck is LOWTRAN 7's own fixed-column input (the card formats of the LOWTRAN 7
// source, rev 4.2), so a deck written here also runs in LOWTRAN 7. Integer codes keep
// their LOWTRAN names (lower case); physical values carry their unit in the name.
// Altitudes are above mean sea level; angles in degrees; wavenumbers in cm-1.
#pragma once

#include <array>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/text.hpp"
#include "io/format_handler.hpp"

namespace sigchain::io {

// CARD 1: MODEL,ITYPE,IEMSCT,IMULT,M1..M6,MDEF,IM,NOPRT,TBOUND,SALB  FORMAT(13I5,F8.3,F7.2)
struct CdkCard1 {
    int model = 0;  // 0 user meteorological data (horizontal only), 1-6 standard, 7 radiosonde
    int itype = 1;  // path: 1 horizontal, 2 slant between two altitudes, 3 slant to space
    int iemsct =
        0;  // 0 transmittance, 1 radiance, 2 radiance with solar scattering, 3 solar irradiance
    int imult = 0;                      // 1 multiple scattering
    std::array<int, 6> m{};             // M1..M6: 0 or a model 1-6 for T/P, H2O, O3, CH4, N2O, CO
    int mdef = 0;                       // 1 default profiles for the other gases
    int im = 0;                         // 1 read a user profile (CARD 2C) in this run
    int noprt = 0;                      // 1 minimal printing
    double boundary_temperature_k = 0;  // TBOUND (0: first level's temperature)
    double surface_albedo = 0;          // SALB, 0..1 (0: black body)
    bool operator==(const CdkCard1&) const = default;
};

// CARD 2: IHAZE,ISEASN,IVULCN,ICSTL,ICLD,IVSA,VIS,WSS,WHH,RAINRT,GNDALT  FORMAT(6I5,5F10.3)
struct CdkCard2 {
    int ihaze = 0;                  // aerosol model 0-10 (7: user defined, CARD 2D)
    int iseasn = 0;                 // 0 model's season, 1 spring-summer, 2 fall-winter
    int ivulcn = 0;                 // stratospheric aerosol 0-8
    int icstl = 0;                  // air mass character 0-10 (navy maritime only)
    int icld = 0;                   // cloud/rain 0-10, 11 user defined (CARD 2D), 18-20 cirrus
    int ivsa = 0;                   // 1 army vertical structure algorithm (CARD 2B follows)
    double visibility_km = 0;       // VIS (0: the aerosol model's default)
    double wind_speed_m_s = 0;      // WSS
    double wind_speed_24h_m_s = 0;  // WHH
    double rain_rate_mm_h = 0;      // RAINRT
    double ground_altitude_km = 0;  // GNDALT, 0 <= GNDALT < 6
    bool operator==(const CdkCard2&) const = default;
};

// CARD 2A (ICLD 18-20): CTHIK,CALT,CEXT,ISEED  FORMAT(3F10.3,I10)
struct CdkCirrus {
    double thickness_km = 0, base_altitude_km = 0, extinction_km1 = 0;
    long iseed = 0;
    bool operator==(const CdkCirrus&) const = default;
};

// CARD 2B (IVSA=1): ZCVSA,ZTVSA,ZINVSA  FORMAT(3F10.3)
struct CdkVsa {
    double cloud_ceiling_km = 0, cloud_thickness_km = 0, inversion_km = 0;
    bool operator==(const CdkVsa&) const = default;
};

// CARD 2C3 (IRD2=1): AHAZE,EQLWCZ,RRATZ,IHA1,ICLD1,IVUL1,ISEA1,ICHR  FORMAT(10X,3F10.3,5I5)
struct CdkLayerAerosol {
    double extinction_km1 = 0;     // AHAZE at 0.55 um
    double liquid_water_g_m3 = 0;  // EQLWCZ
    double rain_rate_mm_h = 0;     // RRATZ
    int iha1 = 0, icld1 = 0, ivul1 = 0, isea1 = 0, ichr = 0;
    bool operator==(const CdkLayerAerosol&) const = default;
};

// CARD 2C1: ZMDL,P,T,WMOL(1..3),JCHAR  FORMAT(F10.3,5E10.3,15A1), then CARD 2C2 (IRD1=1)
// and CARD 2C3 (IRD2=1). The units of P, T and the gas amounts are given by JCHAR.
struct CdkLayer {
    double altitude_km = 0;
    double pressure = 0;           // JCHAR(1): blank/A mb, B atm, C torr, 1-6 model
    double temperature = 0;        // JCHAR(2): blank/A K, B deg C, 1-6 model
    std::array<double, 3> wmol{};  // H2O, CO2, O3 (JCHAR(3..5))
    std::string jchar;             // up to 15 unit letters, trailing blanks dropped
    std::optional<std::array<double, 9>> wmol_4_12;  // CARD 2C2: N2O CO CH4 O2 NO SO2 NO2 NH3 HNO3
    std::optional<CdkLayerAerosol> aerosol;          // CARD 2C3
    bool operator==(const CdkLayer&) const = default;
};

// CARD 2C (MODEL 0 or 7, IM=1): ML,IRD1,IRD2,TITLE  FORMAT(3I5,18A4), then ML layers.
struct CdkProfile {
    int ird1 = 0, ird2 = 0;
    std::string title;             // up to 72 characters, trailing blanks dropped
    std::vector<CdkLayer> layers;  // ML = layers.size(), 1..34, altitude increasing
    bool operator==(const CdkProfile&) const = default;
};

// The 47 wavelengths (um) of LOWTRAN 7's aerosol and cloud tables (EXTDTA's VX2), to
// which CARD 2D2's coefficients belong.
inline constexpr int kCdkUserWavelengths = 47;
extern const std::array<double, kCdkUserWavelengths> kCdkUserWavelengths_um;

// One region's CARD 2D1 (AWCCON,TITLE  FORMAT(E10.3,18A4)) and CARD 2D2
// ((VX(I),EXTC(N,I),ABSC(N,I),ASYM(N,I),I=1,47)  FORMAT(3(F6.2,2F7.5,F6.4)), 16 lines).
struct CdkUserRegion {
    double liquid_water_g_m3 = 0;  // AWCCON, equivalent liquid water content
    std::string title;             // up to 72 characters, trailing blanks dropped
    std::array<double, kCdkUserWavelengths> wavelength_um{};  // VX, the tables' wavelengths
    std::array<double, kCdkUserWavelengths> extinction{};     // EXTC, 1 at 0.55 um for aerosols
    std::array<double, kCdkUserWavelengths> absorption{};     // ABSC, same unit, <= EXTC
    std::array<double, kCdkUserWavelengths> asymmetry{};      // ASYM, in (-1, 1)
    bool operator==(const CdkUserRegion&) const = default;
};

// CARD 2D (IHAZE=7 or ICLD=11): IREG(1..4)  FORMAT(4I5), then CARD 2D1 and 2D2 for each
// region with IREG 1 (LOWTRAN 7 subroutine RDEXA). Regions in LOWTRAN's order: boundary
// layer, troposphere, stratosphere, upper atmosphere (with ICLD 11: boundary layer, the
// cloud, troposphere, stratosphere).
struct CdkUserOptics {
    std::array<std::optional<CdkUserRegion>, 4> regions;  // set where IREG is 1
    bool operator==(const CdkUserOptics&) const = default;
};

// CARD 3B2 (IPH=1): ANGF,F(1..4)  FORMAT(5E10.3)
struct CdkPhaseAngle {
    double angle_deg = 0;
    std::array<double, 4> phase_function_sr1{};  // boundary layer, troposphere, stratosphere, above
    bool operator==(const CdkPhaseAngle&) const = default;
};

// CARD 3 (H1,H2,ANGLE,RANGE,BETA,RO,LEN  FORMAT(6F10.3,I5)) or, when IEMSCT=3, the
// ALTERNATE CARD 3 (H1,H2,ANGLE,IDAY,RO,ISOURC,ANGLEM  FORMAT(3F10.3,I5,5X,F10.3,I5,F10.3));
// with IEMSCT=2, CARD 3A1 (IPARM,IPH,IDAY,ISOURC  FORMAT(4I5)), CARD 3A2
// (PARM1-4,TIME,PSIPO,ANGLEM,G  FORMAT(8F10.3)) and with IPH=1 CARD 3B1/3B2.
// Fields a layout does not have stay 0.
struct CdkGeometry {
    double h1_km = 0, h2_km = 0;        // observer, final altitude
    double zenith_angle_deg = 0;        // ANGLE at H1, 0 up .. 180 down
    double range_km = 0;                // RANGE (CARD 3)
    double earth_center_angle_deg = 0;  // BETA (CARD 3)
    double earth_radius_km = 0;         // RO (0: the model's radius)
    int len = 0;                        // LEN (CARD 3): 1 long path through the tangent height
    int iparm = 0, iph = 0;             // CARD 3A1
    int iday = 0;                       // day of year (CARD 3A1 or alternate CARD 3)
    int isourc = 0;                     // 0 sun, 1 moon
    std::array<double, 4> parm{};       // IPARM 0/1: observer lat (deg N), lon (deg W, 0..360), ...
    double time_h = 0;                  // Greenwich time, decimal hours
    double path_azimuth_deg = 0;        // PSIPO, east of north
    double moon_phase_angle_deg = 0;    // ANGLEM
    double asymmetry_g = 0;             // G (Henyey-Greenstein, IPH=0)
    std::vector<CdkPhaseAngle> phase_function;  // CARD 3B (IPH=1), 1..50 angles
    bool operator==(const CdkGeometry&) const = default;
};

// CARD 4: V1,V2,DV  FORMAT(3F10.3)
struct CdkSpectral {
    double v1_cm1 = 0, v2_cm1 = 0, dv_cm1 = 0;  // 0 <= V1 < V2 <= 50000, DV > 0
    bool operator==(const CdkSpectral&) const = default;
};

// Which cards a run's text holds: all of them (the first run, or after IRPT=1), only
// the CARD 3 group (after IRPT=3) or only CARD 4 (after IRPT=4).
enum class CdkRunKind { Full, Geometry, Spectral };

// One LOWTRAN run, resolved: the cards a run does not repeat (and a profile reused
// with IM=0) hold the values in force from the earlier runs.
struct CdkRun {
    CdkRunKind kind = CdkRunKind::Full;
    CdkCard1 card1;
    CdkCard2 card2;
    std::optional<CdkCirrus> cirrus;           // CARD 2A
    std::optional<CdkVsa> vsa;                 // CARD 2B
    std::optional<CdkProfile> profile;         // CARD 2C and its layers (MODEL 0 or 7)
    std::optional<CdkUserOptics> user_optics;  // CARD 2D (IHAZE 7 or ICLD 11)
    CdkGeometry geometry;
    CdkSpectral spectral;
    int irpt = 0;  // CARD 5: 0 end, 1 all cards again, 3 CARD 3 again, 4 CARD 4 again
    bool operator==(const CdkRun&) const = default;
};

struct Cdk {
    std::vector<CdkRun> runs;  // the last has IRPT 0
    bool operator==(const Cdk&) const = default;
};

inline constexpr int kCdkMaxLayers = 34;       // LOWTRAN 7's ML limit
inline constexpr int kCdkMaxPhaseAngles = 50;  // NANGLS limit
inline constexpr double kCdkMaxWavenumber_cm1 = 50000;

// Reads a deck (fixed columns, no comments); throws DataError naming the card, field
// and columns of the first problem.
Cdk parse_cdk(const TextInput& in);
// Writes the deck in LOWTRAN 7's columns (trailing blanks dropped). Throws
// sigchain::Error if a value does not fit its field.
void write_cdk(std::ostream& out, const Cdk& cdk);
// Writes CARD 2D, 2D1 and 2D2 (cdk_card2d.cpp).
void write_cdk_card2d(std::ostream& out, const CdkUserOptics& user);
inline Cdk read_cdk_file(const std::string& path) { return parse_cdk(TextInput::from_file(path)); }
FormatHandler cdk_format();

}  // namespace sigchain::io

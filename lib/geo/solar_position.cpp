// NREL Solar Position Algorithm (Reda and Andreas, NREL/TP-560-34302, 2003 rev. 2008);
// equation numbers below are the report's. The periodic-term tables are the report's
// tables A4.2 (Earth heliocentric longitude, latitude, radius) and A4.3 (nutation).
#include "geo/solar_position.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>

#include "core/error.hpp"
#include "core/numeric.hpp"

namespace sigchain::geo {

namespace {

// One periodic term A cos(B + C * JME) of table A4.2 (A in 1e-8 rad or 1e-8 AU, B rad,
// C rad per Julian millennium).
struct Term {
    double a, b, c;
};

// Table A4.2, Earth heliocentric longitude L0-L5.
constexpr Term kL0[] = {
    {175347046, 0, 0},           {3341656, 4.6692568, 6283.07585},
    {34894, 4.6261, 12566.1517}, {3497, 2.7441, 5753.3849},
    {3418, 2.8289, 3.5231},      {3136, 3.6277, 77713.7715},
    {2676, 4.4181, 7860.4194},   {2343, 6.1352, 3930.2097},
    {1324, 0.7425, 11506.7698},  {1273, 2.0371, 529.691},
    {1199, 1.1096, 1577.3435},   {990, 5.233, 5884.927},
    {902, 2.045, 26.298},        {857, 3.508, 398.149},
    {780, 1.179, 5223.694},      {753, 2.533, 5507.553},
    {505, 4.583, 18849.228},     {492, 4.205, 775.523},
    {357, 2.92, 0.067},          {317, 5.849, 11790.629},
    {284, 1.899, 796.298},       {271, 0.315, 10977.079},
    {243, 0.345, 5486.778},      {206, 4.806, 2544.314},
    {205, 1.869, 5573.143},      {202, 2.458, 6069.777},
    {156, 0.833, 213.299},       {132, 3.411, 2942.463},
    {126, 1.083, 20.775},        {115, 0.645, 0.98},
    {103, 0.636, 4694.003},      {102, 0.976, 15720.839},
    {102, 4.267, 7.114},         {99, 6.21, 2146.17},
    {98, 0.68, 155.42},          {86, 5.98, 161000.69},
    {85, 1.3, 6275.96},          {85, 3.67, 71430.7},
    {80, 1.81, 17260.15},        {79, 3.04, 12036.46},
    {75, 1.76, 5088.63},         {74, 3.5, 3154.69},
    {74, 4.68, 801.82},          {70, 0.83, 9437.76},
    {62, 3.98, 8827.39},         {61, 1.82, 7084.9},
    {57, 2.78, 6286.6},          {56, 4.39, 14143.5},
    {56, 3.47, 6279.55},         {52, 0.19, 12139.55},
    {52, 1.33, 1748.02},         {51, 0.28, 5856.48},
    {49, 0.49, 1194.45},         {41, 5.37, 8429.24},
    {41, 2.4, 19651.05},         {39, 6.17, 10447.39},
    {37, 6.04, 10213.29},        {37, 2.57, 1059.38},
    {36, 1.71, 2352.87},         {36, 1.78, 6812.77},
    {33, 0.59, 17789.85},        {30, 0.44, 83996.85},
    {30, 2.74, 1349.87},         {25, 3.16, 4690.48},
};
constexpr Term kL1[] = {
    {628331966747, 0, 0},       {206059, 2.678235, 6283.07585},
    {4303, 2.6351, 12566.1517}, {425, 1.59, 3.523},
    {119, 5.796, 26.298},       {109, 2.966, 1577.344},
    {93, 2.59, 18849.23},       {72, 1.14, 529.69},
    {68, 1.87, 398.15},         {67, 4.41, 5507.55},
    {59, 2.89, 5223.69},        {56, 2.17, 155.42},
    {45, 0.4, 796.3},           {36, 0.47, 775.52},
    {29, 2.65, 7.11},           {21, 5.34, 0.98},
    {19, 1.85, 5486.78},        {19, 4.97, 213.3},
    {17, 2.99, 6275.96},        {16, 0.03, 2544.31},
    {16, 1.43, 2146.17},        {15, 1.21, 10977.08},
    {12, 2.83, 1748.02},        {12, 3.26, 5088.63},
    {12, 5.27, 1194.45},        {12, 2.08, 4694},
    {11, 0.77, 553.57},         {10, 1.3, 6286.6},
    {10, 4.24, 1349.87},        {9, 2.7, 242.73},
    {9, 5.64, 951.72},          {8, 5.3, 2352.87},
    {6, 2.65, 9437.76},         {6, 4.67, 4690.48},
};
constexpr Term kL2[] = {
    {52919, 0, 0},     {8720, 1.0721, 6283.0758}, {309, 0.867, 12566.152}, {27, 0.05, 3.52},
    {16, 5.19, 26.3},  {16, 3.68, 155.42},        {10, 0.76, 18849.23},    {9, 2.06, 77713.77},
    {7, 0.83, 775.52}, {5, 4.66, 1577.34},        {4, 1.03, 7.11},         {4, 3.44, 5573.14},
    {3, 5.14, 796.3},  {3, 6.05, 5507.55},        {3, 1.19, 242.73},       {3, 6.12, 529.69},
    {3, 0.31, 398.15}, {3, 2.28, 553.57},         {2, 4.38, 5223.69},      {2, 3.75, 0.98},
};
constexpr Term kL3[] = {
    {289, 5.844, 6283.076}, {35, 0, 0},         {17, 5.49, 12566.15}, {3, 5.2, 155.42},
    {1, 4.72, 3.52},        {1, 5.3, 18849.23}, {1, 5.97, 242.73},
};
constexpr Term kL4[] = {{114, 3.142, 0}, {8, 4.13, 6283.08}, {1, 3.84, 12566.15}};
constexpr Term kL5[] = {{1, 3.14, 0}};

// Table A4.2, Earth heliocentric latitude B0-B1.
constexpr Term kB0[] = {
    {280, 3.199, 84334.662}, {102, 5.422, 5507.553}, {80, 3.88, 5223.69},
    {44, 3.7, 2352.87},      {32, 4, 1577.34},
};
constexpr Term kB1[] = {{9, 3.9, 5507.55}, {6, 1.73, 5223.69}};

// Table A4.2, Earth radius vector R0-R4.
constexpr Term kR0[] = {
    {100013989, 0, 0},
    {1670700, 3.0984635, 6283.07585},
    {13956, 3.05525, 12566.1517},
    {3084, 5.1985, 77713.7715},
    {1628, 1.1739, 5753.3849},
    {1576, 2.8469, 7860.4194},
    {925, 5.453, 11506.77},
    {542, 4.564, 3930.21},
    {472, 3.661, 5884.927},
    {346, 0.964, 5507.553},
    {329, 5.9, 5223.694},
    {307, 0.299, 5573.143},
    {243, 4.273, 11790.629},
    {212, 5.847, 1577.344},
    {186, 5.022, 10977.079},
    {175, 3.012, 18849.228},
    {110, 5.055, 5486.778},
    {98, 0.89, 6069.78},
    {86, 5.69, 15720.84},
    {86, 1.27, 161000.69},
    {65, 0.27, 17260.15},
    {63, 0.92, 529.69},
    {57, 2.01, 83996.85},
    {56, 5.24, 71430.7},
    {49, 3.25, 2544.31},
    {47, 2.58, 775.52},
    {45, 5.54, 9437.76},
    {43, 6.01, 6275.96},
    {39, 5.36, 4694},
    {38, 2.39, 8827.39},
    {37, 0.83, 19651.05},
    {37, 4.9, 12139.55},
    {36, 1.67, 12036.46},
    {35, 1.84, 2942.46},
    {33, 0.24, 7084.9},
    {32, 0.18, 5088.63},
    {32, 1.78, 398.15},
    {28, 1.21, 6286.6},
    {28, 1.9, 6279.55},
    {26, 4.59, 10447.39},
};
constexpr Term kR1[] = {
    {103019, 1.10749, 6283.07585},
    {1721, 1.0644, 12566.1517},
    {702, 3.142, 0},
    {32, 1.02, 18849.23},
    {31, 2.84, 5507.55},
    {25, 1.32, 5223.69},
    {18, 1.42, 1577.34},
    {10, 5.91, 10977.08},
    {9, 1.42, 6275.96},
    {9, 0.27, 5486.78},
};
constexpr Term kR2[] = {
    {4359, 5.7846, 6283.0758}, {124, 5.579, 12566.152}, {12, 3.14, 0},
    {9, 3.63, 77713.77},       {6, 1.87, 5573.14},      {3, 5.47, 18849.23},
};
constexpr Term kR3[] = {{145, 4.273, 6283.076}, {7, 3.92, 12566.15}};
constexpr Term kR4[] = {{4, 2.56, 6283.08}};

// Table A4.3: nutation terms. Multipliers Y0..Y4 of X0..X4, then a, b (longitude,
// 0.0001 arcsec and per century) and c, d (obliquity).
struct NutationTerm {
    int y[5];
    double a, b, c, d;
};
constexpr NutationTerm kNutation[] = {
    {{0, 0, 0, 0, 1}, -171996, -174.2, 92025, 8.9},
    {{-2, 0, 0, 2, 2}, -13187, -1.6, 5736, -3.1},
    {{0, 0, 0, 2, 2}, -2274, -0.2, 977, -0.5},
    {{0, 0, 0, 0, 2}, 2062, 0.2, -895, 0.5},
    {{0, 1, 0, 0, 0}, 1426, -3.4, 54, -0.1},
    {{0, 0, 1, 0, 0}, 712, 0.1, -7, 0},
    {{-2, 1, 0, 2, 2}, -517, 1.2, 224, -0.6},
    {{0, 0, 0, 2, 1}, -386, -0.4, 200, 0},
    {{0, 0, 1, 2, 2}, -301, 0, 129, -0.1},
    {{-2, -1, 0, 2, 2}, 217, -0.5, -95, 0.3},
    {{-2, 0, 1, 0, 0}, -158, 0, 0, 0},
    {{-2, 0, 0, 2, 1}, 129, 0.1, -70, 0},
    {{0, 0, -1, 2, 2}, 123, 0, -53, 0},
    {{2, 0, 0, 0, 0}, 63, 0, 0, 0},
    {{0, 0, 1, 0, 1}, 63, 0.1, -33, 0},
    {{2, 0, -1, 2, 2}, -59, 0, 26, 0},
    {{0, 0, -1, 0, 1}, -58, -0.1, 32, 0},
    {{0, 0, 1, 2, 1}, -51, 0, 27, 0},
    {{-2, 0, 2, 0, 0}, 48, 0, 0, 0},
    {{0, 0, -2, 2, 1}, 46, 0, -24, 0},
    {{2, 0, 0, 2, 2}, -38, 0, 16, 0},
    {{0, 0, 2, 2, 2}, -31, 0, 13, 0},
    {{0, 0, 2, 0, 0}, 29, 0, 0, 0},
    {{-2, 0, 1, 2, 2}, 29, 0, -12, 0},
    {{0, 0, 0, 2, 0}, 26, 0, 0, 0},
    {{-2, 0, 0, 2, 0}, -22, 0, 0, 0},
    {{0, 0, -1, 2, 1}, 21, 0, -10, 0},
    {{0, 2, 0, 0, 0}, 17, -0.1, 0, 0},
    {{2, 0, -1, 0, 1}, 16, 0, -8, 0},
    {{-2, 2, 0, 2, 2}, -16, 0.1, 7, 0},
    {{0, 1, 0, 0, 1}, -15, 0, 9, 0},
    {{-2, 0, 1, 0, 1}, -13, 0, 7, 0},
    {{0, -1, 0, 0, 1}, -12, 0, 6, 0},
    {{0, 0, 2, -2, 0}, 11, 0, 0, 0},
    {{2, 0, -1, 2, 1}, -10, 0, 5, 0},
    {{2, 0, 1, 2, 2}, -8, 0, 3, 0},
    {{0, 1, 0, 2, 2}, 7, 0, -3, 0},
    {{-2, 1, 1, 0, 0}, -7, 0, 0, 0},
    {{0, -1, 0, 2, 2}, -7, 0, 3, 0},
    {{2, 0, 0, 2, 1}, -7, 0, 3, 0},
    {{2, 0, 1, 0, 0}, 6, 0, 0, 0},
    {{-2, 0, 2, 2, 2}, 6, 0, -3, 0},
    {{-2, 0, 1, 2, 1}, 6, 0, -3, 0},
    {{2, 0, -2, 0, 1}, -6, 0, 3, 0},
    {{2, 0, 0, 0, 1}, -6, 0, 3, 0},
    {{0, -1, 1, 0, 0}, 5, 0, 0, 0},
    {{-2, -1, 0, 2, 1}, -5, 0, 3, 0},
    {{-2, 0, 0, 0, 1}, -5, 0, 3, 0},
    {{0, 0, 2, 2, 1}, -5, 0, 3, 0},
    {{-2, 0, 2, 0, 1}, 4, 0, 0, 0},
    {{-2, 1, 0, 2, 1}, 4, 0, 0, 0},
    {{0, 0, 1, -2, 0}, 4, 0, 0, 0},
    {{-1, 0, 1, 0, 0}, -4, 0, 0, 0},
    {{-2, 1, 0, 0, 0}, -4, 0, 0, 0},
    {{1, 0, 0, 0, 0}, -4, 0, 0, 0},
    {{0, 0, 1, 2, 0}, 3, 0, 0, 0},
    {{0, 0, -2, 2, 2}, -3, 0, 0, 0},
    {{-1, -1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, 1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, -1, 1, 2, 2}, -3, 0, 0, 0},
    {{2, -1, -1, 2, 2}, -3, 0, 0, 0},
    {{0, 0, 3, 2, 2}, -3, 0, 0, 0},
    {{2, -1, 0, 2, 2}, -3, 0, 0, 0},
};
static_assert(std::size(kNutation) == 63, "table A4.3 has 63 rows");

// Eq. 9: sum of A cos(B + C JME) over one table.
double series(std::span<const Term> terms, double jme) {
    double sum = 0;
    for (const Term& t : terms) sum += t.a * std::cos(t.b + t.c * jme);
    return sum;
}

// Eq. 10-11 (and 12 for B and R): the polynomial in JME of the series, / 1e8.
double earth_value(std::span<const std::span<const Term>> tables, double jme) {
    double sum = 0, power = 1;
    for (const auto& table : tables) {
        sum += series(table, jme) * power;
        power *= jme;
    }
    return sum / 1e8;
}

double wrap_360(double deg) {
    double r = std::fmod(deg, 360.0);
    return r < 0 ? r + 360.0 : r;
}

void check_range(double value, double lo, double hi, const char* what) {
    if (!(value >= lo && value <= hi))
        throw Error("solar position: " + std::string(what) + " out of range [" +
                    std::to_string(lo) + ", " + std::to_string(hi) + "]: " + std::to_string(value));
}

}  // namespace

double julian_day(int year, int month, int day, double ut_hours, double delta_ut1_s) {
    // Eq. 4 with the day's fraction from UT + delta UT1.
    double day_fraction = day + (ut_hours + delta_ut1_s / 3600.0) / 24.0;
    int y = year, m = month;
    if (m < 3) {
        y -= 1;
        m += 12;
    }
    double jd =
        std::floor(365.25 * (y + 4716.0)) + std::floor(30.6001 * (m + 1)) + day_fraction - 1524.5;
    if (jd > 2299160.0) {  // Gregorian calendar
        double a = std::floor(y / 100.0);
        jd += 2 - a + std::floor(a / 4);
    }
    return jd;
}

double default_delta_t_s(int year) {
    // Espenak and Meeus (2006) polynomial fits, t in years from 2000.
    double t = year - 2000.0;
    if (year >= 1986 && year < 2005)
        return 63.86 + 0.3345 * t - 0.060374 * t * t + 0.0017275 * t * t * t +
               0.000651814 * t * t * t * t + 0.00002373599 * t * t * t * t * t;
    if (year >= 2005 && year < 2050) return 62.92 + 0.32217 * t + 0.005589 * t * t;
    if (year >= 2050 && year <= 2150) {
        double u = (year - 1820.0) / 100.0;
        return -20 + 32 * u * u - 0.5628 * (2150.0 - year);
    }
    return 69;
}

SolarPosition solar_position(const SolarPositionInput& in) {
    check_range(in.year, -2000, 6000, "year");
    check_range(in.month, 1, 12, "month");
    check_range(in.day, 1, 31, "day");
    check_range(in.ut_hours, 0, 24, "time (hours ut)");
    check_range(in.latitude_deg, -90, 90, "latitude (deg)");
    check_range(in.longitude_east_deg, -180, 180, "longitude (deg east)");
    check_range(in.pressure_mb, 0, 5000, "pressure (mb)");
    check_range(in.temperature_c, -273, 6000, "temperature (deg c)");

    SolarPosition out;
    // 3.1 Julian and ephemeris day, century, millennium (eq. 4-8).
    const double jd = julian_day(in.year, in.month, in.day, in.ut_hours, in.delta_ut1_s);
    const double jde = jd + in.delta_t_s / 86400.0;
    const double jc = (jd - 2451545.0) / 36525.0;
    const double jce = (jde - 2451545.0) / 36525.0;
    const double jme = jce / 10.0;
    out.julian_day = jd;

    // 3.2 Earth heliocentric longitude, latitude (deg) and radius vector (AU).
    const std::span<const Term> l_tables[] = {kL0, kL1, kL2, kL3, kL4, kL5};
    const std::span<const Term> b_tables[] = {kB0, kB1};
    const std::span<const Term> r_tables[] = {kR0, kR1, kR2, kR3, kR4};
    const double l_deg = wrap_360(earth_value(l_tables, jme) / kRadPerDeg);
    const double b_deg = earth_value(b_tables, jme) / kRadPerDeg;
    const double r_au = earth_value(r_tables, jme);
    out.earth_sun_distance_au = r_au;

    // 3.3 Geocentric longitude and latitude (eq. 13-14).
    const double theta_deg = wrap_360(l_deg + 180.0);
    const double beta_deg = -b_deg;

    // 3.4 Nutation in longitude and obliquity (eq. 15-23), X in degrees.
    const double jce2 = jce * jce, jce3 = jce2 * jce;
    const double x[5] = {
        297.85036 + 445267.111480 * jce - 0.0019142 * jce2 + jce3 / 189474.0,
        357.52772 + 35999.050340 * jce - 0.0001603 * jce2 - jce3 / 300000.0,
        134.96298 + 477198.867398 * jce + 0.0086972 * jce2 + jce3 / 56250.0,
        93.27191 + 483202.017538 * jce - 0.0036825 * jce2 + jce3 / 327270.0,
        125.04452 - 1934.136261 * jce + 0.0020708 * jce2 + jce3 / 450000.0,
    };
    double sum_psi = 0, sum_eps = 0;
    for (const NutationTerm& t : kNutation) {
        double arg = 0;
        for (int j = 0; j < 5; ++j) arg += x[j] * t.y[j];
        arg *= kRadPerDeg;
        sum_psi += (t.a + t.b * jce) * std::sin(arg);
        sum_eps += (t.c + t.d * jce) * std::cos(arg);
    }
    const double delta_psi_deg = sum_psi / 36000000.0;
    const double delta_eps_deg = sum_eps / 36000000.0;

    // 3.5 True obliquity of the ecliptic (eq. 24-25), epsilon0 in arcsec.
    const double u = jme / 10.0;
    static constexpr double kObliquity[] = {84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
                                            -39.05,    7.12,     27.87, 5.79,    2.45};
    double eps0_arcsec = 0, upow = 1;
    for (double c : kObliquity) {
        eps0_arcsec += c * upow;
        upow *= u;
    }
    const double eps_deg = eps0_arcsec / 3600.0 + delta_eps_deg;
    const double eps = eps_deg * kRadPerDeg;

    // 3.6-3.7 Aberration correction and apparent sun longitude (eq. 26-27).
    const double delta_tau_deg = -20.4898 / (3600.0 * r_au);
    const double lambda = (theta_deg + delta_psi_deg + delta_tau_deg) * kRadPerDeg;

    // 3.8 Apparent sidereal time at Greenwich (eq. 28-29).
    const double nu0_deg = wrap_360(280.46061837 + 360.98564736629 * (jd - 2451545.0) +
                                    0.000387933 * jc * jc - jc * jc * jc / 38710000.0);
    const double nu_deg = nu0_deg + delta_psi_deg * std::cos(eps);

    // 3.9-3.10 Geocentric sun right ascension and declination (eq. 30-31).
    const double beta = beta_deg * kRadPerDeg;
    const double alpha_deg =
        wrap_360(std::atan2(std::sin(lambda) * std::cos(eps) - std::tan(beta) * std::sin(eps),
                            std::cos(lambda)) /
                 kRadPerDeg);
    const double delta = std::asin(std::sin(beta) * std::cos(eps) +
                                   std::cos(beta) * std::sin(eps) * std::sin(lambda));

    // 3.11 Observer local hour angle (eq. 32).
    const double h = wrap_360(nu_deg + in.longitude_east_deg - alpha_deg) * kRadPerDeg;

    // 3.12 Topocentric right ascension and declination (eq. 33-38).
    const double xi = 8.794 / (3600.0 * r_au) * kRadPerDeg;
    const double phi = in.latitude_deg * kRadPerDeg;
    const double uu = std::atan(0.99664719 * std::tan(phi));
    const double xx = std::cos(uu) + in.elevation_m / 6378140.0 * std::cos(phi);
    const double yy = 0.99664719 * std::sin(uu) + in.elevation_m / 6378140.0 * std::sin(phi);
    const double denom = std::cos(delta) - xx * std::sin(xi) * std::cos(h);
    const double delta_alpha = std::atan2(-xx * std::sin(xi) * std::sin(h), denom);
    const double delta_prime =
        std::atan2((std::sin(delta) - yy * std::sin(xi)) * std::cos(delta_alpha), denom);

    // 3.13 Topocentric local hour angle (eq. 39).
    const double h_prime = h - delta_alpha;
    out.declination_deg = delta_prime / kRadPerDeg;
    out.hour_angle_deg = h_prime / kRadPerDeg;

    // 3.14 Topocentric zenith angle (eq. 40-44).
    const double e0_deg = std::asin(std::sin(phi) * std::sin(delta_prime) +
                                    std::cos(phi) * std::cos(delta_prime) * std::cos(h_prime)) /
                          kRadPerDeg;
    double delta_e_deg = 0;
    if (e0_deg >= -(0.26667 + in.refraction_at_sunrise_deg))  // sun above the horizon
        delta_e_deg = in.pressure_mb / 1010.0 * 283.0 / (273.0 + in.temperature_c) * 1.02 /
                      (60.0 * std::tan((e0_deg + 10.3 / (e0_deg + 5.11)) * kRadPerDeg));
    out.zenith_no_refraction_deg = 90.0 - e0_deg;
    out.zenith_deg = 90.0 - (e0_deg + delta_e_deg);

    // 3.15 Topocentric azimuth, eastward from north (eq. 45-46).
    const double gamma_deg =
        std::atan2(std::sin(h_prime),
                   std::cos(h_prime) * std::sin(phi) - std::tan(delta_prime) * std::cos(phi)) /
        kRadPerDeg;
    out.azimuth_deg = wrap_360(gamma_deg + 180.0);
    return out;
}

SolarPosition solar_position(const SceneSite& site, double elevation_m) {
    SolarPositionInput in;
    in.year = site.year;
    in.month = site.month;
    in.day = site.day;
    in.ut_hours = site.time_gmt_hours;
    in.delta_t_s = default_delta_t_s(site.year);
    in.latitude_deg = site.latitude_deg;
    // The .snd's east-positive longitude may be given in [0, 360).
    in.longitude_east_deg =
        site.longitude_east_deg > 180 ? site.longitude_east_deg - 360 : site.longitude_east_deg;
    in.elevation_m = elevation_m;
    return solar_position(in);
}

}  // namespace sigchain::geo

// Reading Landsat MTL metadata (man mtl(5)): the scene's date, time, corners, sun and
// per-band calibration from the ODL statements of Collection 1, Collection 2 and older files.
#include "io/mtl.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

namespace sigchain::io {

namespace {

// The statements by key. A key given twice with different values is an error when it is
// asked for (Collection 2 repeats some keys in several groups, with the same value).
class Keys {
public:
    Keys(const TextInput& in, const Odl& odl) : m_in(in), m_end(odl.end_line) {
        for (const auto& s : odl.statements) {
            if (s.kind != OdlStatement::Kind::Value) continue;
            auto [it, inserted] = m_first.emplace(s.entry.key, &s.entry);
            if (!inserted && it->second->value != s.entry.value && !m_conflict.count(s.entry.key))
                m_conflict[s.entry.key] = &s.entry;
        }
    }
    const OdlEntry* find(const std::string& key) const {
        auto it = m_first.find(key);
        if (it == m_first.end()) return nullptr;
        if (auto c = m_conflict.find(key); c != m_conflict.end())
            throw DataError(m_in.at(c->second->line),
                            key + " given again with another value (first on line " +
                                std::to_string(it->second->line) + ")");
        return it->second;
    }
    // The first of `names` present; DataError at the END line when none is.
    const OdlEntry& require(std::initializer_list<const char*> names) const {
        std::string list;
        for (const char* n : names) {
            if (const OdlEntry* e = find(n)) return *e;
            list += (list.empty() ? "" : " or ") + std::string(n);
        }
        throw DataError(m_in.at(m_end), "missing " + list + " (a required MTL value)");
    }
    double number(const OdlEntry& e, double lo, double hi) const {
        return parse_in_range(e.value, m_in.at(e.line), e.key, lo, hi);
    }
    SourceLocation at(const OdlEntry& e) const { return m_in.at(e.line); }
    const std::map<std::string, const OdlEntry*>& all() const { return m_first; }

private:
    const TextInput& m_in;
    int m_end;
    std::map<std::string, const OdlEntry*> m_first, m_conflict;
};

bool leap(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

// YYYY-MM-DD.
void parse_date(const Keys& keys, const OdlEntry& e, Mtl& mtl) {
    int y = 0, m = 0, d = 0;
    char tail = 0;
    static const int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (e.value.size() != 10 || std::sscanf(e.value.c_str(), "%4d-%2d-%2d%c", &y, &m, &d, &tail) != 3 ||
        y < 1972 || m < 1 || m > 12 || d < 1 || d > days[m - 1] + (m == 2 && leap(y)))
        throw DataError(keys.at(e), "expected " + e.key + " as YYYY-MM-DD (a valid date from 1972), found " +
                                        quoted(e.value));
    mtl.year = y, mtl.month = m, mtl.day = d;
}

// HH:MM:SS[.fraction][Z] -> decimal hours.
double parse_time(const Keys& keys, const OdlEntry& e) {
    std::string t = e.value;
    if (!t.empty() && t.back() == 'Z') t.pop_back();
    auto bad = [&] {
        return DataError(keys.at(e), "expected " + e.key + " as HH:MM:SS.fffZ (GMT), found " +
                                         quoted(e.value));
    };
    if (t.size() < 8 || t[2] != ':' || t[5] != ':') throw bad();
    double h = 0, m = 0, s = 0;
    if (!std::isdigit(static_cast<unsigned char>(t[0])) || !try_parse_double(t.substr(0, 2), h) ||
        !try_parse_double(t.substr(3, 2), m) || !try_parse_double(t.substr(6), s) ||
        !std::isdigit(static_cast<unsigned char>(t[6])) || h > 23 || m > 59 || s < 0 || s >= 60 ||
        h != std::floor(h) || m != std::floor(m))
        throw bad();
    return h + m / 60 + s / 3600;
}

std::string normalise_id(std::string id) {
    for (char& c : id) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (id.rfind("LANDSAT", 0) == 0 && id.size() > 7 && std::isdigit(static_cast<unsigned char>(id[7])))
        id.insert(7, "_");  // the older "Landsat7"
    if (id == "ETM+") id = "ETM";
    return id;
}

// The older format's band numbers: 61, 62 are ETM+'s band 6 low and high gain.
std::string band_name(const std::string& old) {
    if (old == "61") return "6_VCID_1";
    if (old == "62") return "6_VCID_2";
    return old;
}

// Which band (and which field of it) a key sets; "" when it sets none.
struct BandKey {
    std::string band;
    std::string field;  // mult add max min qmin qmax k1 k2 gain
};

BandKey classify(const std::string& key) {
    static const std::pair<const char*, const char*> modern[] = {
        {"RADIANCE_MULT_BAND_", "mult"}, {"RADIANCE_ADD_BAND_", "add"},
        {"RADIANCE_MAXIMUM_BAND_", "max"}, {"RADIANCE_MINIMUM_BAND_", "min"},
        {"QUANTIZE_CAL_MAX_BAND_", "qmax"}, {"QUANTIZE_CAL_MIN_BAND_", "qmin"},
        {"K1_CONSTANT_BAND_", "k1"}, {"K2_CONSTANT_BAND_", "k2"}, {"GAIN_BAND_", "gain"}};
    for (auto [prefix, field] : modern)
        if (key.rfind(prefix, 0) == 0 && key.size() > std::strlen(prefix))
            return {key.substr(std::strlen(prefix)), field};
    static const std::pair<const char*, const char*> older[] = {
        {"LMAX_BAND", "max"}, {"LMIN_BAND", "min"}, {"QCALMAX_BAND", "qmax"}, {"QCALMIN_BAND", "qmin"}};
    auto digits = [](const std::string& s) {
        return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    };
    for (auto [prefix, field] : older)
        if (key.rfind(prefix, 0) == 0 && digits(key.substr(std::strlen(prefix))))
            return {band_name(key.substr(std::strlen(prefix))), field};
    if (key == "BAND6_GAIN1") return {"6_VCID_1", "gain"};
    if (key == "BAND6_GAIN2") return {"6_VCID_2", "gain"};
    if (key.rfind("BAND", 0) == 0 && key.size() > 9 && key.compare(key.size() - 5, 5, "_GAIN") == 0 &&
        digits(key.substr(4, key.size() - 9)))
        return {band_name(key.substr(4, key.size() - 9)), "gain"};
    return {};
}

// "1" < "2" < "6_VCID_1" < "6_VCID_2" < "10".
bool band_less(const std::string& a, const std::string& b) {
    auto number = [](const std::string& s) { return std::atol(s.c_str()); };
    if (number(a) != number(b)) return number(a) < number(b);
    return a < b;
}

// A pair that must come together (mult and add, LMAX and LMIN, QCAL max and min).
void require_pair(const Keys& keys, const OdlEntry* a, const OdlEntry* b, const char* b_key) {
    if ((a == nullptr) == (b == nullptr)) return;
    const OdlEntry* given = a ? a : b;
    throw DataError(keys.at(*given), given->key + " without its partner " + b_key);
}

MtlBand read_band(const Keys& keys, const std::string& name,
                  const std::map<std::string, const OdlEntry*>& f, MtlFormat format) {
    auto get = [&](const char* field) -> const OdlEntry* {
        auto it = f.find(field);
        return it == f.end() ? nullptr : it->second;
    };
    auto big = 1e30;
    MtlBand b;
    b.name = name;
    if (auto* e = get("gain")) {
        if (e->value != "H" && e->value != "L")
            throw DataError(keys.at(*e), "expected " + e->key + " \"H\" or \"L\", found " + quoted(e->value));
        b.gain_state = e->value[0], b.gain_line = e->line;
    }
    require_pair(keys, get("mult"), get("add"), ("RADIANCE_ADD_BAND_" + name).c_str());
    require_pair(keys, get("add"), get("mult"), ("RADIANCE_MULT_BAND_" + name).c_str());
    require_pair(keys, get("max"), get("min"), "the radiance minimum");
    require_pair(keys, get("min"), get("max"), "the radiance maximum");
    require_pair(keys, get("qmax"), get("qmin"), "the QCAL minimum");
    require_pair(keys, get("qmin"), get("qmax"), "the QCAL maximum");
    if (auto* e = get("mult")) {
        b.radiance_mult = keys.number(*e, 0, big);
        if (!(*b.radiance_mult > 0)) throw DataError(keys.at(*e), "expected " + e->key + " above 0, found " + quoted(e->value));
        b.radiance_add = keys.number(*get("add"), -big, big);
        b.rescaling_line = e->line;
    }
    if (auto* e = get("max")) {
        b.radiance_max = keys.number(*e, -big, big);
        b.radiance_min = keys.number(*get("min"), -big, big);
        if (!(*b.radiance_max > *b.radiance_min))
            throw DataError(keys.at(*e), "expected " + e->key + " above " + get("min")->key + ", found " + quoted(e->value));
    }
    if (auto* e = get("qmax")) {
        b.qcal_max = keys.number(*e, -big, big);
        b.qcal_min = keys.number(*get("qmin"), -big, big);
        if (!(*b.qcal_max > *b.qcal_min))
            throw DataError(keys.at(*e), "expected " + e->key + " above " + get("qmin")->key + ", found " + quoted(e->value));
    }
    if (auto* e = get("k1")) b.k1 = keys.number(*e, 0, big);
    if (auto* e = get("k2")) b.k2 = keys.number(*e, 0, big);
    // The older format: L = (LMAX - LMIN) / (QCALMAX - QCALMIN) * (QCAL - QCALMIN) + LMIN.
    if (format == MtlFormat::PreCollection && !b.radiance_mult && b.radiance_max) {
        if (!b.qcal_max)
            throw DataError(keys.at(*get("max")), get("max")->key + " without QCALMAX_BAND and QCALMIN_BAND of its band");
        b.radiance_mult = (*b.radiance_max - *b.radiance_min) / (*b.qcal_max - *b.qcal_min);
        b.radiance_add = *b.radiance_min - *b.radiance_mult * *b.qcal_min;
        b.rescaling_line = get("max")->line;
    }
    return b;
}

std::vector<MtlBand> read_bands(const Keys& keys, MtlFormat format) {
    std::map<std::string, std::map<std::string, const OdlEntry*>> fields;
    for (const auto& [key, entry] : keys.all()) {
        BandKey k = classify(key);
        if (k.band.empty()) continue;
        keys.find(key);  // a conflicting repeat is an error
        fields[k.band][k.field] = entry;
    }
    std::vector<std::string> names;
    for (const auto& [name, f] : fields) names.push_back(name);
    std::sort(names.begin(), names.end(), band_less);
    std::vector<MtlBand> bands;
    for (const auto& n : names) bands.push_back(read_band(keys, n, fields[n], format));
    return bands;
}

void read_corners(const Keys& keys, Mtl& mtl) {
    static const char* names[] = {"UL", "UR", "LL", "LR"};
    for (int i = 0; i < 4; ++i) {
        const std::string c = names[i];
        const auto& lat = keys.require({("CORNER_" + c + "_LAT_PRODUCT").c_str(),
                                        ("PRODUCT_" + c + "_CORNER_LAT").c_str()});
        const auto& lon = keys.require({("CORNER_" + c + "_LON_PRODUCT").c_str(),
                                        ("PRODUCT_" + c + "_CORNER_LON").c_str()});
        mtl.corners[i] = {keys.number(lat, -90, 90), keys.number(lon, -180, 180)};
    }
}

}  // namespace

Mtl parse_mtl(const TextInput& in) {
    const Odl odl = parse_odl(in);
    if (odl.statements.empty())
        throw DataError(in.at(odl.end_line), "expected GROUP = L1_METADATA_FILE or LANDSAT_METADATA_FILE before END");
    const auto& first = odl.statements.front().entry;
    if (odl.statements.front().kind != OdlStatement::Kind::Group ||
        (first.value != "L1_METADATA_FILE" && first.value != "LANDSAT_METADATA_FILE"))
        throw DataError(in.at(first.line), "expected GROUP = L1_METADATA_FILE or LANDSAT_METADATA_FILE, found " +
                                               quoted(first.key + " = " + first.value));
    const Keys keys(in, odl);
    Mtl mtl;
    mtl.end_line = odl.end_line;
    mtl.format = first.value == "LANDSAT_METADATA_FILE" ? MtlFormat::Collection2
                 : keys.find("ACQUISITION_DATE") && !keys.find("DATE_ACQUIRED")
                     ? MtlFormat::PreCollection
                     : MtlFormat::Collection1;
    mtl.spacecraft = normalise_id(keys.require({"SPACECRAFT_ID"}).value);
    mtl.sensor = normalise_id(keys.require({"SENSOR_ID"}).value);
    if (const auto* e = keys.find("LANDSAT_PRODUCT_ID")) mtl.product_id = e->value;
    parse_date(keys, keys.require({"DATE_ACQUIRED", "ACQUISITION_DATE"}), mtl);
    mtl.time_gmt_hours = parse_time(keys, keys.require({"SCENE_CENTER_TIME", "SCENE_CENTER_SCAN_TIME"}));
    read_corners(keys, mtl);
    // The sun is informational (sigchain computes it from the date, time and place): a
    // hand-written file for an image with no metadata may leave it out.
    if (const auto* e = keys.find("SUN_AZIMUTH")) {
        const double az = keys.number(*e, -180, 360);
        mtl.sun_azimuth_deg = az < 0 ? az + 360 : az;  // Landsat 8 files give -180 to 180
    }
    if (const auto* e = keys.find("SUN_ELEVATION")) mtl.sun_elevation_deg = keys.number(*e, -90, 90);
    if (const auto* e = keys.find("EARTH_SUN_DISTANCE")) mtl.earth_sun_distance_au = keys.number(*e, 0.9, 1.1);
    mtl.bands = read_bands(keys, mtl.format);
    return mtl;
}

const MtlBand* find_band(const Mtl& mtl, const std::string& name) {
    for (const auto& b : mtl.bands)
        if (b.name == name) return &b;
    return nullptr;
}

const char* format_name(MtlFormat format) {
    switch (format) {
    case MtlFormat::PreCollection: return "pre-collection";
    case MtlFormat::Collection1: return "Collection 1";
    case MtlFormat::Collection2: return "Collection 2";
    }
    return "?";
}

FormatHandler mtl_format() {
    return {"mtl", "Landsat MTL metadata (date, time, corners, sun, band calibration)",
            [](const TextInput& in) {
                Mtl m = parse_mtl(in);
                return std::string(format_name(m.format)) + ", " + m.spacecraft + " " + m.sensor +
                       ", " + std::to_string(m.bands.size()) + " bands";
            },
            [](const TextInput& in, std::ostream& out) {
                parse_mtl(in);
                write_odl(out, parse_odl(in));
            }};
}

}  // namespace sigchain::io

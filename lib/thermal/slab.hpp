// One-dimensional heat conduction through a facet's thickness (White (1996), section 3.4, "Thermal
// Submodel": each facet in isolation, no inter-facet conduction), stepped implicitly.
//
// The slab runs from the front face (x = 0) to the back face (x = thickness). Nodes sit
// on both faces and between them (vertex-centred finite volumes), so the surface
// temperature is a node. Each face exchanges heat with its surroundings through a flux
// the caller linearises about the current state: q_in = source - conductance * T_face.
// Time stepping is backward Euler (unconditionally stable, first order in time; the
// tool's step is 60 s). Not thread-safe per object; separate objects are independent.
#pragma once

#include <vector>

namespace sigchain::thermal {

struct SlabProperties {
    double thickness_m = 0;            // > 0
    double density_kg_m3 = 0;          // > 0
    double specific_heat_j_kg_k = 0;   // > 0
    double conductivity_w_m_k = 0;     // > 0
    double volumetric_power_w_m3 = 0;  // internal (self-generated) heat, spread evenly
};

// The flux into the slab through one face, linearised: q = source - conductance * T,
// W m-2 with T in kelvin. conductance >= 0 (0 and source 0: an insulated face).
struct FaceFlux {
    double source_w_m2 = 0;
    double conductance_w_m2_k = 0;
};

// Node positions: `cells` intervals (>= 1), growing geometrically by `growth` (>= 1)
// from each face toward the middle, so both faces are resolved finely.
std::vector<double> slab_nodes(double thickness_m, int cells, double growth);

class Slab {
public:
    // Throws sigchain::Error for non-positive properties or a bad grid.
    Slab(const SlabProperties& properties, std::vector<double> nodes_m, double initial_k);

    // Advances by dt_s with the face fluxes evaluated at the new temperatures.
    void step(double dt_s, const FaceFlux& front, const FaceFlux& back);

    double front_k() const { return m_t.front(); }
    double back_k() const { return m_t.back(); }
    const std::vector<double>& temperatures_k() const { return m_t; }
    void set_temperatures_k(const std::vector<double>& t);
    // Heat content relative to 0 K, J m-2 (sum of node capacity x temperature).
    double stored_j_m2() const;
    // Heat added by the internal source per second, W m-2.
    double internal_power_w_m2() const;

private:
    SlabProperties m_p;
    std::vector<double> m_x;                 // node positions, m
    std::vector<double> m_capacity;          // J m-2 K-1 per node
    double m_total_capacity = 0;             // J m-2 K-1
    std::vector<double> m_link;              // W m-2 K-1 between node i and i+1
    std::vector<double> m_t;                 // K
    std::vector<double> m_a, m_b, m_c, m_d;  // tridiagonal scratch
};

}  // namespace sigchain::thermal

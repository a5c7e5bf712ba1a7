// Scene library (Embree); see scene.hpp.

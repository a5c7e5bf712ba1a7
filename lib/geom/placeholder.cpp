// Geometry library; see view_angle.hpp.

// Loading a scene file (.gdb, or an .odb assembly of .gdb objects) into a Scene.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace sigchain::scene {

// Loads `path` by its extension. A .gdb has no units: its coordinates are taken to
// be in scene units. An .odb object's coordinates and translations are in its
// UNITS and are scaled to scene units with `scene_meters_per_unit`. Each .gdb file
// is meshed once however many objects and instances use it (Embree instances).
// OBJ and DEM objects are not read yet (NotImplemented; trace's issue adds them).
Scene load_scene_file(const std::string& path, double scene_meters_per_unit);

}  // namespace sigchain::scene

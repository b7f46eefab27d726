#pragma once
// The scene's [walls] table and its [[obstacle]] tables (solver/SCENES.md).
#include <vector>

#include "SceneTable.hpp"

namespace sph {

// Reads the wall model and the obstacles into `s`, whose domain, fluid blocks and numerics
// (dx, h/dx) are read already; `domain` is the scene's [domain] table (ghost_pressure is a
// mirror-ghost setting). Throws SceneError naming the key.
void readWalls(SceneTable walls, std::vector<SceneTable> obstacles, SceneTable domain, Scene& s);

}  // namespace sph

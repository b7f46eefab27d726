// Issue 36: the wall_pressure and water_height probes (Diagnostics.hpp) on a 3-D water block at
// rest on the hydrostatic pressure p = rho0 g (H - z), with the block's walls where the probes
// sit. What each must read follows from the definitions: a wetted face reads the hydrostatic
// pressure at its point, a column's free surface sits at the block's top.
#include <gtest/gtest.h>

#include <cmath>

#include "sph/Diagnostics.hpp"

namespace sph {
namespace {

constexpr double g = 9.81, H = 0.4, dx = 0.02;

// Water on the cell-centred lattice of [0, L] x [0, W] x [0, H] (the floor z = 0 and the faces
// x = 0 and x = L are the block's walls), rho from the inverse Tait EOS, m = rho dx^3.
struct Block {
  Scene scene;
  Particles<3> fluid;
  InteractionSet<3> set;  // unused by these probes
  Block(double L, double W, double depth = H) {
    scene.dimension = 3, scene.dx = dx, scene.hOverDx = 1.33, scene.kernel = KernelKind::quadratic;
    scene.lower = {0, 0, 0}, scene.upper = {L, W, 1.0};
    scene.bodyAcceleration = {0, 0, -g};
    Phase water;
    water.rho0 = 1000, water.c0 = 10 * std::sqrt(2 * g * H);
    scene.phases = {water};
    const int nx = int(std::lround(L / dx)), ny = int(std::lround(W / dx)),
              nz = int(std::lround(depth / dx));
    fluid.resize(std::size_t(nx) * ny * nz);
    std::size_t k = 0;
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < ny; ++j)
        for (int l = 0; l < nz; ++l, ++k) {
          fluid.r[k] = Vec<3>((i + 0.5) * dx, (j + 0.5) * dx, (l + 0.5) * dx);
          fluid.p[k] = water.rho0 * g * (depth - fluid.r[k][2]);
          fluid.rho[k] = TaitEquationOfState::density(fluid.p[k], water);
          fluid.m[k] = fluid.rho[k] * dx * dx * dx, fluid.h[k] = 1.33 * dx, fluid.phase[k] = 0;
          fluid.v[k] = Vec<3>::Zero();
        }
  }
  double read(const std::string& type, std::vector<double> at) const {
    Probe p;
    p.type = type, p.position = std::move(at);
    return probe<3>(scene, p, fluid, set);
  }
};

TEST(WallProbe, WettedFaceReadsTheHydrostaticPressure) {
  const Block b(0.4, 0.4);
  // On the face x = L at mid-width, at depths from 0.5 H to 0.05 H above the floor; and on the
  // floor. Without the g term of eq. (27) the reading is the pressure at the fluid's centroid
  // within 2 h, ~0.6 dx inside the face: at most rho g dx below it (196 Pa here). With it, the
  // remaining error is the kernel sum's lattice error (~1 % of p, Kernels' sum test) and, near
  // the floor, the cut support: 2 % of rho g H (78 Pa) bounds both.
  for (double z : {0.2, 0.1, 0.05, 0.02}) {
    const double exact = 1000 * g * (H - z);
    EXPECT_NEAR(b.read("wall_pressure", {0.4, 0.2, z}), exact, 0.02 * 1000 * g * H) << "z = " << z;
  }
  EXPECT_NEAR(b.read("wall_pressure", {0.2, 0.2, 0.0}), 1000 * g * H, 0.02 * 1000 * g * H);
}

TEST(WallProbe, DryPointReadsZero) {
  const Block b(0.4, 0.4);
  // 2 h = 0.053 m above the free surface no fluid is within reach; 0.03 m above, the kernel sum
  // is below the dry threshold 0.1.
  EXPECT_EQ(b.read("wall_pressure", {0.4, 0.2, H + 0.06}), 0.0);
  EXPECT_EQ(b.read("wall_pressure", {0.4, 0.2, H + 0.03}), 0.0);
}

TEST(WallProbe, WaterHeightFindsTheFreeSurface) {
  const Block b(0.4, 0.4);
  // The fluid fraction falls through 1/2 at the lattice's top face, H, to within the kernel's
  // lattice error: dx/4 bounds it (the sampling is dx/8, interpolated).
  EXPECT_NEAR(b.read("water_height", {0.2, 0.2}), H, 0.25 * dx);
  // At a wall the line sees half a support: phi reaches 1/2 only deep in the column, not at
  // its surface; the probe then reads below H, never above.
  EXPECT_LE(b.read("water_height", {0.4, 0.2}), H + 0.25 * dx);
  // Beside the block, beyond 2 h from every particle: dry.
  Block narrow(0.2, 0.4);
  narrow.scene.upper = {1.0, 0.4, 1.0};
  EXPECT_EQ(narrow.read("water_height", {0.5, 0.2}), 0.0);
}

// A film of 1-6 layers on a floor that is a wall: the floor's mirror fills the support it cuts,
// so each film reads its depth to within dx/4 (as the free surface above), with the paper's
// kernel and with Wendland C2 at h/dx 2 (measured: within 0.07 dx). On an open floor nothing
// fills the cut: one layer's phi stays below 1/2 and it reads dry, which is what the mirror is for.
TEST(WallProbe, FilmOnAWallFloorReadsItsDepth) {
  for (int layers = 1; layers <= 6; ++layers) {
    Block cut(0.4, 0.4, layers * dx), wall(0.4, 0.4, layers * dx);
    wall.scene.faces[2][0] = FaceKind::free_slip;
    EXPECT_NEAR(wall.read("water_height", {0.2, 0.2}), layers * dx, 0.25 * dx) << layers;
    if (layers == 1) EXPECT_EQ(cut.read("water_height", {0.2, 0.2}), 0.0);
    wall.scene.kernel = KernelKind::wendland_c2, wall.scene.hOverDx = 2;
    for (std::size_t k = 0; k < wall.fluid.size(); ++k) wall.fluid.h[k] = 2 * dx;
    EXPECT_NEAR(wall.read("water_height", {0.2, 0.2}), layers * dx, 0.25 * dx)
        << layers << " layers, Wendland C2 at h/dx 2";
  }
}

TEST(WallProbe, LoneDropletIsNoWaterHeight) {
  Block b(0.4, 0.4);
  // One particle 0.3 m above the surface: phi at most V W(0) ~ 0.13 < 1/2.
  b.fluid.resize(b.fluid.size() + 1);
  const std::size_t k = b.fluid.size() - 1;
  b.fluid.r[k] = Vec<3>(0.2, 0.2, 0.7), b.fluid.rho[k] = 1000, b.fluid.m[k] = 1000 * dx * dx * dx;
  b.fluid.h[k] = 1.33 * dx, b.fluid.phase[k] = 0, b.fluid.v[k] = Vec<3>::Zero(), b.fluid.p[k] = 0;
  EXPECT_NEAR(b.read("water_height", {0.2, 0.2}), H, 0.25 * dx);
}

}  // namespace
}  // namespace sph

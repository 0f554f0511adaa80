// The paper's ironing problem: a half-disc tool on a long substrate.
#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

namespace ContactDynamics
{
  namespace
  {
    class Ironing : public BuiltInScene<2>
    {
    protected:
      std::vector<BodyDefinition<2>>
      bodies() const override
      {
        using namespace MeshSteps;
        // 200 elements along the top; vertically a geometric progression
        // from the top element length down to coarser cells.
        const unsigned int nx = scaled(200);
        return {half_disc_body("tool",
                               Point<2>(1.2, 5.02),
                               1.0,
                               scaled(16),
                               scaled(12),
                               1.0,
                               scaled(16)),
                rectangle_body("substrate",
                               Point<2>(0, 0),
                               Point<2>(12, 4),
                               uniform(12, nx),
                               reversed(geometric(4, 12.0 / nx, scaled(30))))};
      }
    };
  } // namespace

  SceneEntry
  ironing_scene()
  {
    return planar_scene<Ironing>(
      "ironing",
      "the paper's half-disc tool pressed into and sliding along a substrate");
  }
} // namespace ContactDynamics

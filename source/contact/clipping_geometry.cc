#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <contact_dynamics/contact/clipping_geometry.h>

#include <map>
#include <mutex>

namespace ContactDynamics
{
  namespace ClippingGeometry
  {
    const TriangleRule &
    triangle_rule(const unsigned int n_points_1d)
    {
      AssertThrow(n_points_1d >= 1 && n_points_1d <= 7,
                  dealii::ExcMessage(
                    "Triangle rules exist for 1 to 7 points per direction, "
                    "not " +
                    std::to_string(n_points_1d) + "."));
      static std::map<unsigned int, TriangleRule> rules;
      static std::mutex                           mutex;
      std::lock_guard<std::mutex>                 lock(mutex);
      auto                                       &rule = rules[n_points_1d];
      if (rule.empty())
        {
          // (the reference triangle (0,0), (1,0), (0,1) has area 1/2)
          const dealii::QWitherdenVincentSimplex<2> q(n_points_1d);
          for (unsigned int i = 0; i < q.size(); ++i)
            {
              const auto &p = q.point(i);
              rule.push_back(
                {{{1. - p[0] - p[1], p[0], p[1]}}, 2 * q.weight(i)});
            }
        }
      return rule;
    }
  } // namespace ClippingGeometry
} // namespace ContactDynamics

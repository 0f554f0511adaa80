// Which nodes of a partly covered face of degree 2 keep their multiplier
// (mortar_contact_quadratic.cc in 2-D, mortar_contact_quadratic_3d.cc in
// 3-D): those whose covered integral of N_j is at least 10 % of their
// whole-face one; if none, the best covered.
#ifndef contact_dynamics_contact_kept_multiplier_nodes_h
#define contact_dynamics_contact_kept_multiplier_nodes_h

#include <array>
#include <vector>

namespace ContactDynamics
{
  template <std::size_t n>
  std::vector<unsigned int>
  kept_multiplier_nodes(const std::array<double, n> &covered,
                        const std::array<double, n> &whole)
  {
    constexpr double          dropped_fraction = 0.1;
    std::vector<unsigned int> kept;
    unsigned int              best = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        if (covered[j] >= dropped_fraction * whole[j])
          kept.push_back(j);
        if (covered[j] / whole[j] > covered[best] / whole[best])
          best = j;
      }
    if (kept.empty())
      kept.push_back(best);
    return kept;
  }
} // namespace ContactDynamics

#endif

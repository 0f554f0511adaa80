// SurfaceContact: what the search and the assembly do differently for a
// pair whose primary side is a rigid obstacle. The obstacles' state, the
// reaction on them and their work: ObstacleCoupling (obstacle_coupling.cc).
#include <contact_dynamics/contact/surface_contact.h>

namespace ContactDynamics
{
  template <int dim>
  void
  SurfaceContact<dim>::set_times(const double committed, const double trial)
  {
    obstacles.set_times(committed, trial);
  }

  template <int dim>
  std::vector<types::global_dof_index>
  SurfaceContact<dim>::obstacle_patch_unknowns(const PairData    &pair,
                                               const unsigned int patch) const
  {
    const auto                           nodes = patch_nodes(pair, patch);
    std::vector<types::global_dof_index> unknowns;
    for (const unsigned int n : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        unknowns.push_back(pair.secondary.dofs[n][d]);
    for (unsigned int c = dim; c < 2 * dim; ++c)
      for (const unsigned int n : nodes)
        unknowns.push_back(pair.secondary.dofs[n][c]);
    return unknowns;
  }

  template <int dim>
  std::vector<std::vector<unsigned int>>
  SurfaceContact<dim>::obstacle_candidates(const PairData   &pair,
                                           const VectorType &u,
                                           const double margin_factor) const
  {
    // {0} for a patch whose swept box comes within its margin of the
    // obstacle at either time (the signed distance changes by at most the
    // distance between two points)
    std::vector<std::vector<unsigned int>> result(n_patches(pair));
    for (unsigned int p = 0; p < n_patches(pair); ++p)
      if (pair.handled_patch[p] || pair.assembled_patch[p])
        {
          const BoundingBox<dim> box =
            swept_patch_box(pair, p, u, margin_factor);
          const auto     corners = box.get_boundary_points();
          const double   reach   = corners.first.distance(corners.second) / 2;
          Tensor<1, dim> normal;
          for (const auto *place : {&pair.committed_place, &pair.trial_place})
            if (pair.obstacle->signed_distance(*place,
                                               Tensor<1, dim>(box.center()),
                                               normal) <= reach)
              result[p] = {0};
        }
    return result;
  }

#define INSTANTIATE(dim)                                                    \
  template void SurfaceContact<dim>::set_times(const double, const double); \
  template std::vector<types::global_dof_index>                             \
  SurfaceContact<dim>::obstacle_patch_unknowns(const PairData &,            \
                                               const unsigned int) const;   \
  template std::vector<std::vector<unsigned int>>                           \
  SurfaceContact<dim>::obstacle_candidates(const PairData &,                \
                                           const VectorType &,              \
                                           const double) const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics

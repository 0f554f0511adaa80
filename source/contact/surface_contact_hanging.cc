// SurfaceContact: secondary and primary surface nodes that hang on an
// adapted mesh (hanging_surface_dofs.h). Their nodal sums go to the nodes
// they follow.
#include <contact_dynamics/contact/surface_contact.h>

namespace ContactDynamics
{
  template <int dim>
  void
  SurfaceContact<dim>::add_hanging_constraints(
    AffineConstraints<double> &constraints) const
  {
    hanging.add_constraints(constraints);
  }

  template <int dim>
  void
  SurfaceContact<dim>::move_hanging_sums(PairData &pair) const
  {
    if (hanging.empty())
      return;
    for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
      if (!pair.hanging_parents[j].empty())
        {
          const auto   sums = pair.node_sums(j);
          const double own  = force_per_gap_sum(pair, j);
          for (const auto &[k, weight] : pair.hanging_parents[j])
            {
              const double factor = weight * own / force_per_gap_sum(pair, k);
              const auto   target = pair.node_sums(k);
              for (unsigned int q = 0; q < sums.size(); ++q)
                {
                  target[q]->value += factor * sums[q]->value;
                  for (const auto &[i, d] : sums[q]->derivatives)
                    target[q]->derivatives[i] += factor * d;
                }
            }
          for (LinearizedValue *q : sums)
            *q = LinearizedValue();
        }
  }

#define INSTANTIATE(dim)                                      \
  template void SurfaceContact<dim>::add_hanging_constraints( \
    AffineConstraints<double> &) const;                       \
  template void SurfaceContact<dim>::move_hanging_sums(PairData &) const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics

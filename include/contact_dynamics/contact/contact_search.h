// Candidate primary faces for each secondary face, from bounding boxes in
// an R-tree (n log n instead of all pairs).
#ifndef contact_dynamics_contact_contact_search_h
#define contact_dynamics_contact_contact_search_h

#include <deal.II/base/bounding_box.h>

#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * For each secondary box, the indices of the primary boxes it intersects
   * (sorted).
   */
  template <int dim>
  std::vector<std::vector<unsigned int>>
  find_candidate_pairs(const std::vector<BoundingBox<dim>> &secondary,
                       const std::vector<BoundingBox<dim>> &primary);
} // namespace ContactDynamics

#endif

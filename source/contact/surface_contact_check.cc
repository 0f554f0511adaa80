// SurfaceContact: the check of a converged step for secondary nodes that
// went through a primary face unnoticed or penetrate too deep (doc/contact.md,
// "Search"); the passage through a face per dimension in
// surface_contact_check_2d.cc and _3d.cc.
#include <deal.II/base/utilities.h>

#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/contact/face_passage.h>
#include <contact_dynamics/contact/setup_caveats.h>
#include <contact_dynamics/contact/surface_contact.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace ContactDynamics
{
  template <int dim>
  std::string
  SurfaceContact<dim>::check_step(const VectorType &u) const
  {
    // A node that the step's contact conditions did not hold back (see
    // doc/contact.md, "Search"): (1) not active at the converged state, yet
    // its straight path relative to a primary face passed through the face
    // from outside and ends more than `depth` behind it; or (2) projected
    // with a penetration beyond `own_depth`: a converged gap condition
    // leaves none, a held node none deeper than half a primary element.
    std::string message;
    for (unsigned int p = 0; p < pairs.size() && message.empty(); ++p)
      {
        const PairData &pair  = pairs[p];
        const auto      faces = candidate_faces(pair);
        for (unsigned int j = 0;
             j < pair.secondary.n_nodes() && message.empty();
             ++j)
          if (pair.owned_node[j])
            message = check_node(p, j, faces[j], u);
      }
    if (!message.empty())
      message += "; the step is rejected and a smaller one tried";
    // the same decision on every process
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      for (const auto &m : Utilities::MPI::all_gather(comm, message))
        if (!m.empty())
          return m;
    return message;
  }

  template <int dim>
  std::vector<std::set<unsigned int>>
  SurfaceContact<dim>::candidate_faces(const PairData &pair) const
  {
    std::vector<std::set<unsigned int>> faces(pair.secondary.n_nodes());
    for (unsigned int e = 0; e < n_patches(pair); ++e)
      if (pair.handled_patch[e])
        for (const unsigned int j : patch_nodes(pair, e))
          faces[j].insert(pair.candidates[e].begin(), pair.candidates[e].end());
    return faces;
  }

  template <int dim>
  std::string
  SurfaceContact<dim>::check_node(const unsigned int            p,
                                  const unsigned int            j,
                                  const std::set<unsigned int> &faces,
                                  const VectorType             &u) const
  {
    const PairData  &pair = pairs[p];
    const auto      &s    = pair.secondary;
    const NodeState &node = pair.nodes[j];
    // a hanging node is held with the nodes it follows, on average:
    // where one of them is in contact, it is judged by them
    if (std::any_of(pair.hanging_parents[j].begin(),
                    pair.hanging_parents[j].end(),
                    [&](const auto &parent) {
                      const NodeState &q = pair.nodes[parent.first];
                      return q.active || q.persistent;
                    }))
      return {};
    const Point<dim>   x0 = s.position(j, search.committed_u);
    const Point<dim>   x1 = s.position(j, u);
    std::ostringstream failure;
    failure << "contact pair '" << contact.pairs[p].name
            << "': the secondary node at " << coordinates(x1) << " (reference "
            << coordinates(s.reference[j]) << ", at " << coordinates(x0)
            << " at the last step) ";
    // a held (persistent) node may sink by dt/2 times the approach rate it
    // had, but not by half the depth of the primary elements it faces:
    // deeper, the mesh no longer resolves the contact (a node may pass a
    // thin body and leave the search's reach)
    double element_depth = 1e300;
    if (pair.obstacle)
      {
        // the obstacle's size, at most the secondary elements'
        element_depth = pair.obstacle->depth();
        for (const unsigned int e : s.node_faces[j])
          element_depth = std::min(element_depth, s.depth[e]);
      }
    else
      for (const unsigned int e : faces)
        element_depth = std::min(element_depth, pair.primary.depth[e]);
    const double own_depth =
      std::max(complementarity.capture_tolerance,
               node.persistent ?
                 0.5 * element_depth :
                 1e-2 * 2 * std::pow(s.reference_weight[j], 1. / (dim - 1)));
    if (node.projected && node.normalized_gap() < -own_depth)
      {
        failure << "penetrates by " << -node.normalized_gap()
                << (node.persistent ?
                      " while held, more than half the depth of the primary "
                      "elements (" :
                      " at its first contact, more than a converged gap "
                      "condition allows (")
                << own_depth << ")";
        return failure.str();
      }
    // (a node held in this step enforces its gap rate: it may end inactive
    // behind a face while it separates, within the depth above)
    // (a node behind an obstacle is projected: its gap says so)
    if (node.active || node.persistent)
      return {};
    if (pair.obstacle)
      {
        // a cylinder or sphere that passed over the node within the step
        // (a fast obstacle): its path relative to the obstacle went
        // through the obstacle's inner half and out again. (A node sliding
        // along the surface dips inside by the chord's sagitta only, below
        // half the radius unless it slid by more than the diameter.)
        const double closest =
          pair.obstacle->closest_approach(pair.committed_place,
                                          pair.trial_place,
                                          x0,
                                          x1);
        if (closest >= 0.5 * pair.obstacle->radius())
          return {};
        failure << "was passed by the rigid obstacle within this step: its "
                   "path relative to the obstacle came within "
                << closest << " of its center or axis (Radius = "
                << pair.obstacle->radius()
                << "), but its contact condition is not active";
        return failure.str();
      }
    const std::string passage =
      passage_through_face(pair.primary,
                           faces,
                           x0,
                           x1,
                           search.committed_u,
                           u,
                           complementarity.capture_tolerance);
    if (passage.empty())
      return {};
    failure << passage;
    return failure.str();
  }

  template <int dim>
  std::string
  SurfaceContact<dim>::caveats() const
  {
    using Formulation = ContactParameters::Formulation;
    std::vector<const ContactSurface<dim> *> secondary;
    for (const PairData &pair : pairs)
      secondary.push_back(&pair.secondary);
    const bool  mortar = contact.formulation == Formulation::mortar;
    std::string found =
      complementarity_scale_caveat(contact,
                                   secondary,
                                   complementarity.c_n,
                                   mortar && !complementarity.normalize_c_n,
                                   std::string("Contact/") +
                                     (mortar ? "Mortar" : "Node to segment") +
                                     "/c_n");
    const std::string corner =
      mortar ? secondary_corner_caveat(contact, secondary) : "";
    return found + (found.empty() || corner.empty() ? "" : " ") + corner;
  }

#define INSTANTIATE(dim)                                                   \
  template std::string SurfaceContact<dim>::caveats() const;               \
  template std::string SurfaceContact<dim>::check_step(const VectorType &) \
    const;                                                                 \
  template std::vector<std::set<unsigned int>>                             \
  SurfaceContact<dim>::candidate_faces(const PairData &) const;            \
  template std::string SurfaceContact<dim>::check_node(                    \
    const unsigned int,                                                    \
    const unsigned int,                                                    \
    const std::set<unsigned int> &,                                        \
    const VectorType &) const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics

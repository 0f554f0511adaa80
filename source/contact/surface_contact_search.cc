// SurfaceContact: the swept search for candidate primary faces, the
// sparsity pattern it gives, and the contact zone for mesh refinement.
#include <deal.II/base/utilities.h>

#include <contact_dynamics/contact/contact_search.h>
#include <contact_dynamics/contact/surface_contact.h>

#include <algorithm>
#include <set>

namespace ContactDynamics
{
  template <int dim>
  std::vector<Point<dim>>
  SurfaceContact<dim>::contact_zone(const VectorType &u,
                                    const double      lookahead) const
  {
    // each process its own nodes (their rates are known there)
    std::vector<Point<dim>> points;
    for (const auto &pair : pairs)
      for (unsigned int j = 0; j < pair.nodes.size(); ++j)
        {
          const NodeState &node = pair.nodes[j];
          if (pair.owned_node[j] &&
              (node.active ||
               (node.projected &&
                node.normalized_gap() +
                    std::min(0., node.velocity_rate) * lookahead <=
                  0)))
            points.push_back(pair.secondary.position(j, u));
        }
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return points;
    std::vector<Point<dim>> all;
    for (const auto &part : Utilities::MPI::all_gather(comm, points))
      all.insert(all.end(), part.begin(), part.end());
    return all;
  }

  template <int dim>
  std::vector<std::vector<unsigned int>>
  SurfaceContact<dim>::compute_candidates(const PairData   &pair,
                                          const VectorType &u,
                                          const double      margin_factor) const
  {
    // Boxes around the volume each patch and face sweeps in the step (the
    // union of its boxes at the committed and the trial configuration), so
    // that a body that crosses several elements in one step is still found.
    // Points move linearly within the step in this picture, and a node that
    // passes through a face then lies in both boxes at the crossing.
    if (pair.obstacle)
      return obstacle_candidates(pair, u, margin_factor);
    std::vector<BoundingBox<dim>> secondary, primary;
    std::vector<unsigned int>     handled;
    for (unsigned int p = 0; p < n_patches(pair); ++p)
      if (pair.handled_patch[p] || pair.assembled_patch[p])
        {
          secondary.push_back(swept_patch_box(pair, p, u, margin_factor));
          handled.push_back(p);
        }
    for (unsigned int f = 0; f < pair.primary.n_faces(); ++f)
      {
        double           length = 0, committed_length = 0;
        BoundingBox<dim> box = pair.primary.face_box(f, u, length);
        box.merge_with(
          pair.primary.face_box(f, search.committed_u, committed_length));
        box.extend(margin_factor * std::max(length, committed_length));
        primary.push_back(box);
      }
    const auto found = find_candidate_pairs(secondary, primary);
    std::vector<std::vector<unsigned int>> result(n_patches(pair));
    for (unsigned int k = 0; k < handled.size(); ++k)
      result[handled[k]] = found[k];
    return result;
  }

  template <int dim>
  BoundingBox<dim>
  SurfaceContact<dim>::swept_patch_box(const PairData    &pair,
                                       const unsigned int patch,
                                       const VectorType  &u,
                                       const double       margin_factor) const
  {
    double           size = 0, committed_size = 0;
    BoundingBox<dim> box = patch_box(pair, patch, u, size);
    box.merge_with(patch_box(pair, patch, search.committed_u, committed_size));
    box.extend(margin_factor * std::max(size, committed_size));
    return box;
  }

  template <int dim>
  bool
  SurfaceContact<dim>::update_candidates(const VectorType &u)
  {
    node_history.reinit_fields(owned_dofs, u);
    search.start_search(u);
    bool rebuild = false;
    for (auto &pair : pairs)
      {
        pair.candidates = compute_candidates(pair, u, 0.5);
        if (pair.obstacle && pair.pattern.empty())
          {
            // every patch may meet the obstacle: one pattern for the run
            pair.pattern.assign(n_patches(pair), {0});
            rebuild = true;
          }
        bool covered = !pair.pattern.empty();
        for (unsigned int e = 0; covered && e < pair.candidates.size(); ++e)
          covered = std::includes(pair.pattern[e].begin(),
                                  pair.pattern[e].end(),
                                  pair.candidates[e].begin(),
                                  pair.candidates[e].end());
        if (!covered)
          {
            // a generous margin so that the pattern lasts several steps
            pair.pattern = compute_candidates(pair, u, 2.0);
            rebuild      = true;
          }
      }
    // the sparsity pattern is rebuilt by all processes together
    return Utilities::MPI::logical_or(rebuild, comm);
  }

  template <int dim>
  void
  SurfaceContact<dim>::add_sparsity(DynamicSparsityPattern &dsp) const
  {
    for (const auto &pair : pairs)
      {
        // a node's complementarity row couples to all its patches
        std::vector<std::set<types::global_dof_index>> node_columns(
          pair.secondary.n_nodes());
        for (unsigned int p = 0; p < n_patches(pair); ++p)
          if (pair.handled_patch[p] || pair.assembled_patch[p])
            {
              auto unknowns = pair.obstacle ?
                                obstacle_patch_unknowns(pair, p) :
                                patch_unknowns(pair, p, pair.pattern[p]);
              // and what hanging ones follow
              for (unsigned int i = 0, n = unknowns.size(); i < n; ++i)
                if (const auto *h = hanging.find(unknowns[i]))
                  for (const auto &parent : *h)
                    unknowns.push_back(parent.first);
              // one sorted merge per row, not one search per entry (in 3-D
              // a patch couples about 130 unknowns: half the setup, issue 40)
              std::sort(unknowns.begin(), unknowns.end());
              unknowns.erase(std::unique(unknowns.begin(), unknowns.end()),
                             unknowns.end());
              if (pair.assembled_patch[p])
                for (const auto row : unknowns)
                  dsp.add_entries(row, unknowns.begin(), unknowns.end(), true);
              if (pair.handled_patch[p])
                for (const unsigned int n : patch_nodes(pair, p))
                  {
                    node_columns[n].insert(unknowns.begin(), unknowns.end());
                    for (const auto &parent : pair.hanging_parents[n])
                      node_columns[parent.first].insert(unknowns.begin(),
                                                        unknowns.end());
                  }
            }
        std::vector<types::global_dof_index> columns;
        for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
          if (pair.owned_node[j])
            {
              columns.assign(node_columns[j].begin(), node_columns[j].end());
              dsp.add_entries(pair.secondary.dofs[j][dim],
                              columns.begin(),
                              columns.end(),
                              true);
            }
      }
  }

#define INSTANTIATE(dim)                                                    \
  template std::vector<Point<dim>> SurfaceContact<dim>::contact_zone(       \
    const VectorType &,                                                     \
    const double) const;                                                    \
  template std::vector<std::vector<unsigned int>>                           \
  SurfaceContact<dim>::compute_candidates(const PairData &,                 \
                                          const VectorType &,               \
                                          const double) const;              \
  template BoundingBox<dim> SurfaceContact<dim>::swept_patch_box(           \
    const PairData &,                                                       \
    const unsigned int,                                                     \
    const VectorType &,                                                     \
    const double) const;                                                    \
  template bool SurfaceContact<dim>::update_candidates(const VectorType &); \
  template void SurfaceContact<dim>::add_sparsity(DynamicSparsityPattern &) \
    const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics

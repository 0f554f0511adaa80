// The hanging-node constraints of contact surface dofs, collected from all
// processes, and the Jacobian rows that follow them.
#include <deal.II/base/exceptions.h>

#include <deal.II/dofs/dof_tools.h>

#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/contact/hanging_surface_dofs.h>
#include <contact_dynamics/contact/patch_forces.h>
#include <contact_dynamics/parallel.h>

#include <algorithm>
#include <cstdint>

namespace ContactDynamics
{
  template <int dim>
  void
  HangingSurfaceDofs::collect(const DoFHandler<dim> &dof_handler,
                              const std::set<types::global_dof_index> &surface,
                              const IndexSet &owned_dofs)
  {
    followed.clear();
    AffineConstraints<double> hanging;
    DoFTools::make_hanging_node_constraints(dof_handler, hanging);
    hanging.close();
    // per line: its dof and its (dof, weight) entries, from the owner of
    // the dof
    Message lines;
    for (const auto &line : hanging.get_lines())
      if (!line.entries.empty() && owned_dofs.is_element(line.index) &&
          surface.count(line.index) > 0)
        {
          lines.write_index(line.index);
          lines.write_sparse(line.entries);
        }
    gather_messages(dof_handler.get_communicator(), lines, [&](Message &part) {
      while (!part.at_end())
        {
          auto               &entries = followed[part.read_index()];
          const std::uint64_t n       = part.read_index();
          for (std::uint64_t k = 0; k < n; ++k)
            {
              const types::global_dof_index parent = part.read_index();
              entries.emplace_back(parent, part.read());
            }
        }
    });
  }

  bool
  HangingSurfaceDofs::empty() const
  {
    return followed.empty();
  }

  const HangingSurfaceDofs::Followed *
  HangingSurfaceDofs::find(const types::global_dof_index dof) const
  {
    if (followed.empty())
      return nullptr;
    const auto h = followed.find(dof);
    return h == followed.end() ? nullptr : &h->second;
  }

  void
  HangingSurfaceDofs::add_constraints(
    AffineConstraints<double> &constraints) const
  {
    for (const auto &[dof, entries] : followed)
      if (!constraints.is_constrained(dof))
        {
          constraints.add_line(dof);
          constraints.add_entries(dof, entries);
        }
  }

  template <int dim>
  std::vector<std::vector<std::pair<unsigned int, double>>>
  HangingSurfaceDofs::node_parents(const ContactSurface<dim> &surface,
                                   const unsigned int         component) const
  {
    std::vector<std::vector<std::pair<unsigned int, double>>> parents(
      surface.n_nodes());
    if (followed.empty())
      return parents;
    std::map<types::global_dof_index, unsigned int> node_of;
    for (unsigned int j = 0; j < surface.n_nodes(); ++j)
      node_of[surface.dofs[j][component]] = j;
    for (unsigned int j = 0; j < surface.n_nodes(); ++j)
      if (const Followed *h = find(surface.dofs[j][component]))
        for (const auto &[parent, weight] : *h)
          {
            const auto k = node_of.find(parent);
            AssertThrow(k != node_of.end(),
                        ExcMessage("A hanging node of a contact surface at " +
                                   coordinates(surface.reference[j]) +
                                   " follows a node that is not on that "
                                   "surface."));
            parents[j].emplace_back(k->second, weight);
          }
    return parents;
  }

  std::vector<std::array<unsigned int, 4>>
  HangingSurfaceDofs::edge_subdivisions(const ContactSurface<3> &surface) const
  {
    std::vector<std::array<unsigned int, 4>> result(surface.face_nodes.size(),
                                                    std::array<unsigned int, 4>{
                                                      {1, 1, 1, 1}});
    if (followed.empty() || surface.degree != 2)
      return result;
    // per node: the hanging nodes that follow it, with their weights
    std::map<types::global_dof_index, unsigned int> node_of;
    for (unsigned int j = 0; j < surface.n_nodes(); ++j)
      node_of[surface.dofs[j][0]] = j;
    std::vector<std::vector<std::map<unsigned int, double>>> followers(
      surface.n_nodes());
    for (unsigned int j = 0; j < surface.n_nodes(); ++j)
      if (const Followed *h = find(surface.dofs[j][0]))
        {
          std::map<unsigned int, double> weights;
          for (const auto &[parent, weight] : *h)
            if (const auto k = node_of.find(parent); k != node_of.end())
              weights[k->second] = weight;
          for (const auto &[k, weight] : weights)
            followers[k].push_back(weights);
        }
    // the 9-node face's edges (vertex, mid-side node, vertex) around it
    static constexpr unsigned int edge_nodes[4][3] = {{0, 6, 1},
                                                      {1, 5, 3},
                                                      {3, 7, 2},
                                                      {2, 4, 0}};
    for (unsigned int f = 0; f < surface.face_nodes.size(); ++f)
      for (unsigned int edge = 0; edge < 4; ++edge)
        {
          const unsigned int a = surface.face_nodes[f][edge_nodes[edge][0]],
                             m = surface.face_nodes[f][edge_nodes[edge][1]],
                             b = surface.face_nodes[f][edge_nodes[edge][2]];
          // a node of the edge at t follows a, m, b with the edge's
          // quadratic shape functions at t, and t = N_m(t) / 2 + N_b(t)
          std::vector<double> t{0., 1.};
          for (const auto &weights : followers[m])
            if (std::all_of(weights.begin(), weights.end(), [&](const auto &w) {
                  return w.first == a || w.first == m || w.first == b;
                }))
              t.push_back(weights.at(m) / 2 +
                          (weights.count(b) > 0 ? weights.at(b) : 0.));
          std::sort(t.begin(), t.end());
          double gap = 1;
          for (unsigned int i = 1; i < t.size(); ++i)
            if (t[i] - t[i - 1] > 1e-9)
              gap = std::min(gap, t[i] - t[i - 1]);
          // a finer face's edge holds three nodes: it is twice the gap
          while (result[f][edge] < 64 && result[f][edge] * 2 * gap < 0.99)
            result[f][edge] *= 2;
        }
    return result;
  }

  template <typename Derivatives>
  void
  ContactLinearSystem::add_row(const types::global_dof_index row,
                               const Derivatives            &derivatives,
                               const double                  factor) const
  {
    // one call per row: entry by entry, the matrix's index searches cost as
    // much as the 3-D mortar patches
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    bool                                 redirected = false;
    for (const auto &[column, value] : derivatives)
      if (!constraints.is_constrained(column))
        {
          columns.push_back(column);
          values.push_back(factor * value);
        }
      else if (const auto *h = hanging.find(column))
        for (const auto &[parent, weight] : *h)
          if (!constraints.is_constrained(parent))
            {
              columns.push_back(parent);
              values.push_back(factor * value * weight);
              redirected = true;
            }
    if (redirected)
      {
        // (a column once)
        std::map<types::global_dof_index, double> merged;
        for (unsigned int i = 0; i < columns.size(); ++i)
          merged[columns[i]] += values[i];
        columns.clear();
        values.clear();
        for (const auto &[column, value] : merged)
          {
            columns.push_back(column);
            values.push_back(value);
          }
      }
    if (!columns.empty())
      jacobian.add(row, columns, values);
  }

  template void
  ContactLinearSystem::add_row(
    const types::global_dof_index,
    const std::map<types::global_dof_index, double> &,
    const double) const;
  template void
  ContactLinearSystem::add_row(const types::global_dof_index,
                               const PatchForces::Derivatives &,
                               const double) const;

#define INSTANTIATE(dim)                                             \
  template void HangingSurfaceDofs::collect(                         \
    const DoFHandler<dim> &,                                         \
    const std::set<types::global_dof_index> &,                       \
    const IndexSet &);                                               \
  template std::vector<std::vector<std::pair<unsigned int, double>>> \
  HangingSurfaceDofs::node_parents(const ContactSurface<dim> &,      \
                                   const unsigned int) const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics

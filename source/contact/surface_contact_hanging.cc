// SurfaceContact: secondary and primary surface nodes that hang on an
// adapted mesh. Their forces, Jacobian columns and nodal sums go to the
// nodes they follow.
#include <deal.II/base/exceptions.h>

#include <deal.II/dofs/dof_tools.h>

#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/parallel.h>

#include <cstdint>
#include <map>
#include <set>

namespace ContactDynamics
{
  template <int dim>
  void
  SurfaceContact<dim>::set_up_hanging_parents(PairData &pair) const
  {
    pair.hanging_parents.assign(pair.secondary.n_nodes(), {});
    if (hanging_dofs.empty())
      return;
    std::map<types::global_dof_index, unsigned int> multiplier_node;
    for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
      multiplier_node[pair.secondary.dofs[j][dim]] = j;
    for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
      if (const auto h = hanging_dofs.find(pair.secondary.dofs[j][dim]);
          h != hanging_dofs.end())
        for (const auto &[parent, weight] : h->second)
          {
            const auto k = multiplier_node.find(parent);
            AssertThrow(k != multiplier_node.end(),
                        ExcMessage("A hanging node of a contact surface at " +
                                   coordinates(pair.secondary.reference[j]) +
                                   " follows a node that is not on that "
                                   "surface."));
            pair.hanging_parents[j].emplace_back(k->second, weight);
          }
  }

  template <int dim>
  void
  SurfaceContact<dim>::collect_hanging_dofs(const DoFHandler<dim> &dof_handler)
  {
    hanging_dofs.clear();
    AffineConstraints<double> hanging;
    DoFTools::make_hanging_node_constraints(dof_handler, hanging);
    hanging.close();
    std::set<types::global_dof_index> surface;
    for (const auto &pair : pairs)
      for (const auto *side : {&pair.secondary, &pair.primary})
        for (const auto &node_dofs : side->dofs)
          surface.insert(node_dofs.begin(), node_dofs.end());
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
    gather_messages(comm, lines, [&](Message &part) {
      while (!part.at_end())
        {
          auto               &entries = hanging_dofs[part.read_index()];
          const std::uint64_t n       = part.read_index();
          for (std::uint64_t k = 0; k < n; ++k)
            {
              const types::global_dof_index parent = part.read_index();
              entries.emplace_back(parent, part.read());
            }
        }
    });
  }

  template <int dim>
  void
  SurfaceContact<dim>::add_hanging_constraints(
    AffineConstraints<double> &constraints) const
  {
    for (const auto &[dof, entries] : hanging_dofs)
      if (!constraints.is_constrained(dof))
        {
          constraints.add_line(dof);
          constraints.add_entries(dof, entries);
        }
  }

  template <int dim>
  template <typename Derivatives>
  void
  SurfaceContact<dim>::add_row(const LinearSystem           &system,
                               const types::global_dof_index row,
                               const Derivatives            &derivatives,
                               const double                  factor) const
  {
    // one call per row: entry by entry, the matrix's index searches cost as
    // much as the 3-D mortar patches
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    bool                                 followed = false;
    for (const auto &[column, value] : derivatives)
      if (!system.constraints.is_constrained(column))
        {
          columns.push_back(column);
          values.push_back(factor * value);
        }
      else if (const auto h = hanging_dofs.find(column);
               h != hanging_dofs.end())
        for (const auto &[parent, weight] : h->second)
          if (!system.constraints.is_constrained(parent))
            {
              columns.push_back(parent);
              values.push_back(factor * value * weight);
              followed = true;
            }
    if (followed)
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
      system.jacobian.add(row, columns, values);
  }

  template <int dim>
  void
  SurfaceContact<dim>::move_hanging_sums(PairData &pair) const
  {
    if (hanging_dofs.empty())
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

#define INSTANTIATE(dim)                                                       \
  template void SurfaceContact<dim>::set_up_hanging_parents(PairData &) const; \
  template void SurfaceContact<dim>::collect_hanging_dofs(                     \
    const DoFHandler<dim> &);                                                  \
  template void SurfaceContact<dim>::add_hanging_constraints(                  \
    AffineConstraints<double> &) const;                                        \
  template void SurfaceContact<dim>::add_row(                                  \
    const LinearSystem &,                                                      \
    const types::global_dof_index,                                             \
    const std::map<types::global_dof_index, double> &,                         \
    const double) const;                                                       \
  template void SurfaceContact<dim>::add_row(const LinearSystem &,             \
                                             const types::global_dof_index,    \
                                             const PatchForces::Derivatives &, \
                                             const double) const;              \
  template void SurfaceContact<dim>::move_hanging_sums(PairData &) const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics

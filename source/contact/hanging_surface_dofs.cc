// The hanging-node constraints of contact surface dofs, collected from all
// processes, and the Jacobian rows that follow them.
#include <deal.II/base/exceptions.h>

#include <deal.II/dofs/dof_tools.h>

#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/contact/hanging_surface_dofs.h>
#include <contact_dynamics/contact/patch_forces.h>
#include <contact_dynamics/parallel.h>

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

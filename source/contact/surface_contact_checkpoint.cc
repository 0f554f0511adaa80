// SurfaceContact: the map of the secondary nodes of a checkpoint onto this
// mesh's (by reference position). The history itself is saved and loaded
// by its owners (surface_contact.h, `history`).
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/parameters.h>

#include <array>
#include <map>

namespace ContactDynamics
{
  template <int dim>
  std::vector<std::vector<unsigned int>>
  SurfaceContact<dim>::saved_node_map(const CheckpointData &data) const
  {
    AssertThrow(data.value("contact/pairs") == pairs.size(),
                ExcMessage("The checkpoint has " +
                           format_number(data.value("contact/pairs")) +
                           " contact pairs, the parameters " +
                           std::to_string(pairs.size()) + "."));
    std::vector<std::vector<unsigned int>> maps(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const auto  &nodes = pairs[p].secondary.reference;
        const auto  &saved = data.get(contact_pair_key(p) + "reference");
        const double size  = saved.size() / double(dim);
        AssertThrow(size == nodes.size(),
                    ExcMessage("The checkpoint's contact pair '" +
                               contact.pairs[p].name + "' has " +
                               format_number(size) +
                               " secondary nodes, this mesh " +
                               std::to_string(nodes.size()) + "."));
        bool same = true;
        for (unsigned int j = 0; j < nodes.size() && same; ++j)
          for (unsigned int d = 0; d < dim; ++d)
            same = same && saved[dim * j + d] == nodes[j][d];
        if (same)
          continue;
        std::map<std::array<double, dim>, unsigned int> index;
        for (unsigned int j = 0; j < nodes.size(); ++j)
          {
            AssertThrow(index.emplace(position_key(nodes[j]), j).second,
                        ExcMessage("The contact pair '" +
                                   contact.pairs[p].name +
                                   "' has two secondary nodes at " +
                                   coordinates(nodes[j]) +
                                   ": a checkpoint of another number of "
                                   "processes cannot tell them apart."));
          }
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            Point<dim> where;
            for (unsigned int d = 0; d < dim; ++d)
              where[d] = saved[dim * k + d];
            const auto it = index.find(position_key(where));
            AssertThrow(it != index.end(),
                        ExcMessage("The checkpoint's contact pair '" +
                                   contact.pairs[p].name +
                                   "' has a secondary node at " +
                                   coordinates(where) +
                                   " that this mesh does not have."));
            maps[p].push_back(it->second);
          }
      }
    return maps;
  }

  template std::vector<std::vector<unsigned int>>
  SurfaceContact<2>::saved_node_map(const CheckpointData &) const;
  template std::vector<std::vector<unsigned int>>
  SurfaceContact<3>::saved_node_map(const CheckpointData &) const;
} // namespace ContactDynamics

#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/capture_count.h>
#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/output/checkpoint.h>

namespace ContactDynamics
{
  template <int dim>
  void
  CaptureCount<dim>::commit(const ContactHistoryContext &context)
  {
    // (node states are known on every process after an assembly)
    nodes.resize(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int j = 0; j < pairs[p].nodes.size(); ++j)
        {
          Entry &entry =
            nodes[p][position_key(pairs[p].secondary.reference[j])];
          const bool active = pairs[p].nodes[j].active;
          if (active && !entry.in_contact && !context.reevaluation)
            ++entry.captures;
          entry.in_contact = active;
        }
  }

  template <int dim>
  void
  CaptureCount<dim>::save(CheckpointData &data,
                          const ContactHistoryContext &) const
  {
    for (unsigned int p = 0; p < nodes.size(); ++p)
      {
        std::vector<double> values;
        for (const auto &[x, entry] : nodes[p])
          {
            values.insert(values.end(), x.begin(), x.end());
            values.push_back(entry.captures);
            values.push_back(entry.in_contact);
          }
        data.set(contact_pair_key(p) + "captures", values);
      }
  }

  template <int dim>
  void
  CaptureCount<dim>::load(const CheckpointData &data,
                          const ContactHistoryContext &)
  {
    nodes.assign(pairs.size(), {});
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const std::string name = contact_pair_key(p) + "captures";
        if (!data.has(name))
          {
            // (the node states are loaded already)
            for (unsigned int j = 0; j < pairs[p].nodes.size(); ++j)
              nodes[p][position_key(pairs[p].secondary.reference[j])] =
                {0, pairs[p].nodes[j].active};
            continue;
          }
        const auto &values = data.get(name);
        AssertThrow(values.size() % (dim + 2) == 0,
                    ExcMessage("The checkpoint entry '" + name + "' has " +
                               std::to_string(values.size()) +
                               " values, not a multiple of " +
                               std::to_string(dim + 2) + "."));
        for (std::size_t i = 0; i < values.size(); i += dim + 2)
          {
            std::array<double, dim> x;
            std::copy(&values[i], &values[i] + dim, x.begin());
            nodes[p][x] = {static_cast<unsigned int>(values[i + dim]),
                           values[i + dim + 1] != 0};
          }
      }
  }

  template <int dim>
  void
  CaptureCount<dim>::transfer(const ContactHistoryContext &)
  {
    for (unsigned int p = 0; p < nodes.size() && p < pairs.size(); ++p)
      {
        std::map<std::array<double, dim>, Entry> kept;
        for (const auto &x : pairs[p].secondary.reference)
          if (const auto old = nodes[p].find(position_key(x));
              old != nodes[p].end())
            kept.insert(*old);
        nodes[p] = std::move(kept);
      }
  }

  template <int dim>
  std::vector<NodeColumn>
  CaptureCount<dim>::node_columns(const unsigned int p) const
  {
    NodeColumn column{"captures", std::vector<double>(pairs[p].nodes.size())};
    if (p < nodes.size())
      for (unsigned int j = 0; j < column.values.size(); ++j)
        if (const auto entry =
              nodes[p].find(position_key(pairs[p].secondary.reference[j]));
            entry != nodes[p].end())
          column.values[j] = entry->second.captures;
    return {column};
  }

  template class CaptureCount<2>;
  template class CaptureCount<3>;
} // namespace ContactDynamics

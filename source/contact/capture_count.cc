#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/capture_count.h>
#include <contact_dynamics/output/checkpoint.h>

namespace ContactDynamics
{
  template <int dim>
  typename CaptureCount<dim>::Key
  CaptureCount<dim>::key(const Point<dim> &x)
  {
    Key k;
    for (unsigned int d = 0; d < dim; ++d)
      k[d] = x[d];
    return k;
  }

  template <int dim>
  void
  CaptureCount<dim>::commit(const ContactHistoryContext &)
  {
    // (node states are known on every process after an assembly)
    nodes.resize(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int j = 0; j < pairs[p].nodes.size(); ++j)
        {
          Entry     &entry  = nodes[p][key(pairs[p].secondary.reference[j])];
          const bool active = pairs[p].nodes[j].active;
          if (active && entry.contact == out)
            ++entry.captures;
          entry.contact = active ? in : out;
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
            values.push_back(entry.contact);
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
          continue;
        const auto &values = data.get(name);
        AssertThrow(values.size() % (dim + 2) == 0,
                    ExcMessage("The checkpoint entry '" + name + "' has " +
                               std::to_string(values.size()) +
                               " values, not a multiple of " +
                               std::to_string(dim + 2) + "."));
        for (std::size_t i = 0; i < values.size(); i += dim + 2)
          {
            Key x;
            std::copy(&values[i], &values[i] + dim, x.begin());
            AssertThrow(values[i + dim + 1] >= out &&
                          values[i + dim + 1] <= unknown,
                        ExcMessage("The checkpoint entry '" + name +
                                   "' has a contact state " +
                                   std::to_string(values[i + dim + 1]) +
                                   " (0, 1 or 2 expected)."));
            nodes[p][x] = {static_cast<unsigned int>(values[i + dim]),
                           static_cast<Contact>(values[i + dim + 1])};
          }
      }
  }

  template <int dim>
  void
  CaptureCount<dim>::transfer(const ContactHistoryContext &)
  {
    if (nodes.empty()) // before the first commit
      return;
    nodes.resize(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        std::map<Key, Entry> kept;
        for (const auto &x : pairs[p].secondary.reference)
          {
            const auto old = nodes[p].find(key(x));
            kept[key(x)] =
              old != nodes[p].end() ? old->second : Entry{0, unknown};
          }
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
              nodes[p].find(key(pairs[p].secondary.reference[j]));
            entry != nodes[p].end())
          column.values[j] = entry->second.captures;
    return {column};
  }

  template class CaptureCount<2>;
  template class CaptureCount<3>;
} // namespace ContactDynamics

#include <deal.II/base/utilities.h>

#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/contact/node_history.h>
#include <contact_dynamics/contact/node_state_fields.h>
#include <contact_dynamics/output/checkpoint.h>

namespace ContactDynamics
{
  template <int dim>
  void
  NodeHistory<dim>::commit(const ContactHistoryContext &context)
  {
    gap_field = 0;
    for (auto &field : slip_field)
      field = 0;
    held.resize(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        auto &pair = pairs[p];
        if (!context.reevaluation)
          held[p].clear();
        for (unsigned int j = 0; j < pair.nodes.size(); ++j)
          {
            ContactNodeState &node = pair.nodes[j];
            // a node held in contact through the step carries the Newmark
            // rates of its gap (zero); any other starts holding with the rate
            // of its velocities: the Newmark recursion of a gap that moves
            // freely (over the kinks of sliding faces) rings from step to step
            const bool held_in_contact = node.persistent && node.active;
            node.held_gap              = node.normalized_gap();
            // (Capture = position: it starts at rest, holding its gap)
            node.held_rate = !node.projected ? 0. :
                             held_in_contact ? node.gap_rate :
                             complementarity.capture_at_position ?
                                               0. :
                                               node.velocity_rate;
            node.held_acceleration =
              node.projected && held_in_contact ? node.gap_acceleration : 0.;
            node.persistent =
              complementarity.holds_contact() && node.projected &&
              node.normalized_gap() <= complementarity.capture_tolerance;
            if (pair.owned_node[j])
              {
                gap_field(pair.secondary.dofs[j][dim]) = node.normalized_gap();
                for (unsigned int a = 0; a + 1 < dim; ++a)
                  slip_field[a](pair.secondary.dofs[j][dim]) =
                    node.slip_rate[a];
              }
            pair.position[j] = pair.secondary.position(j, *context.u);
            keep_held(p, j, context.reevaluation);
          }
      }
    gap_field.compress(VectorOperation::insert);
    for (auto &field : slip_field)
      field.compress(VectorOperation::insert);
  }

  template <int dim>
  void
  NodeHistory<dim>::keep_held(const unsigned int p,
                              const unsigned int j,
                              const bool         reevaluation)
  {
    ContactNodeState &node = pairs[p].nodes[j];
    const auto        key  = position_key(pairs[p].secondary.reference[j]);
    if (!reevaluation)
      {
        if (node.persistent)
          held[p][key] = {
            {node.held_gap, node.held_rate, node.held_acceleration}};
        return;
      }
    const auto before = held[p].find(key);
    if (before == held[p].end())
      return;
    node.held_gap          = before->second[0];
    node.held_rate         = before->second[1];
    node.held_acceleration = before->second[2];
    node.persistent        = true;
  }

  template <int dim>
  void
  NodeHistory<dim>::save(CheckpointData &data,
                         const ContactHistoryContext &) const
  {
    const auto        &fields   = node_state_fields();
    const unsigned int n_fields = fields.size();
    data.set("contact/pairs", pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const auto         &pair = pairs[p];
        const std::string   key  = contact_pair_key(p);
        const unsigned int  n    = pair.nodes.size();
        std::vector<double> states(n_fields * n, 0.), reference;
        // each node from the process that owns it (zeros elsewhere)
        for (unsigned int j = 0; j < n; ++j)
          if (pair.owned_node[j])
            for (unsigned int f = 0; f < n_fields; ++f)
              states[n_fields * j + f] = fields[f].get(pair.nodes[j]);
        Utilities::MPI::sum(states, comm, states);
        for (const auto &x : pair.secondary.reference)
          reference.insert(reference.end(), x.begin_raw(), x.end_raw());
        data.set(key + "nodes", states);
        data.set(key + "reference", reference);
      }
  }

  template <int dim>
  void
  NodeHistory<dim>::load(const CheckpointData        &data,
                         const ContactHistoryContext &context)
  {
    const auto        &fields   = node_state_fields();
    const unsigned int n_fields = fields.size();
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        auto              &pair = pairs[p];
        const auto        &map  = (*context.node_maps)[p];
        const unsigned int n    = pair.nodes.size();
        const auto        &states =
          data.get(contact_pair_key(p) + "nodes", n_fields * n);
        for (unsigned int k = 0; k < n; ++k)
          {
            const unsigned int j = map.empty() ? k : map[k];
            for (unsigned int f = 0; f < n_fields; ++f)
              fields[f].set(pair.nodes[j], states[n_fields * k + f]);
          }
        for (unsigned int j = 0; j < n; ++j)
          pair.position[j] = pair.secondary.position(j, *context.u);
      }
  }

  template <int dim>
  void
  NodeHistory<dim>::transfer(const ContactHistoryContext &)
  {
    gap_field.clear();
    for (auto &field : slip_field)
      field.clear();
  }

  template <int dim>
  void
  NodeHistory<dim>::list_vectors(std::vector<VectorType *> &vectors)
  {
    vectors.push_back(&gap_field);
    for (auto &field : slip_field)
      vectors.push_back(&field);
  }

  template <int dim>
  void
  NodeHistory<dim>::reinit_fields(const IndexSet   &owned_dofs,
                                  const VectorType &u)
  {
    if (gap_field.size() != u.size())
      {
        gap_field.reinit(owned_dofs, comm);
        for (auto &field : slip_field)
          field.reinit(owned_dofs, comm);
      }
  }

  template class NodeHistory<2>;
  template class NodeHistory<3>;
} // namespace ContactDynamics

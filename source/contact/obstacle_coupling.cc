#include <contact_dynamics/contact/obstacle_coupling.h>
#include <contact_dynamics/contact/surface_geometry_3d.h>
#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/parallel.h>

#include <algorithm>
#include <cmath>

namespace ContactDynamics
{
  namespace
  {
    // (2-D: the tangent is the rotated normal)
    unsigned int
    reference_tangent_axis(const ContactSurface<2> &, const unsigned int)
    {
      return 0;
    }

    unsigned int
    reference_tangent_axis(const ContactSurface<3> &s, const unsigned int j)
    {
      return ClippingGeometry::tangent_axis(s, j);
    }
  } // namespace

  template <int dim>
  void
  ObstacleCoupling<dim>::set_up(ContactPairData<dim>          &pair,
                                const RigidObstacleParameters &parameters) const
  {
    pair.obstacle = std::make_shared<const RigidObstacle<dim>>(parameters);
    pair.committed_place = pair.obstacle->placement(committed_time);
    pair.trial_place     = pair.obstacle->placement(trial_time);
    pair.reaction = pair.committed_reaction = {};
    const auto &s                           = pair.secondary;
    pair.dof_node.clear();
    pair.tangent_axis.assign(s.n_nodes(), 0);
    for (unsigned int j = 0; j < s.n_nodes(); ++j)
      {
        for (unsigned int d = 0; d < dim; ++d)
          pair.dof_node[s.dofs[j][d]] = {j, d};
        // from the surface's own reference normal, as for meshed pairs: the
        // obstacle's normal at the start says nothing about where it will
        // touch the node (a sphere moving diagonally)
        pair.tangent_axis[j] = reference_tangent_axis(s, j);
      }
  }

  template <int dim>
  void
  ObstacleCoupling<dim>::set_times(const double committed, const double trial)
  {
    committed_time = committed;
    trial_time     = trial;
    for (auto &pair : pairs)
      if (pair.obstacle)
        {
          pair.committed_place = pair.obstacle->placement(committed);
          pair.trial_place     = pair.obstacle->placement(trial);
        }
  }

  template <int dim>
  void
  ObstacleCoupling<dim>::add_reaction(ContactPairData<dim> &pair,
                                      const PatchForces    &forces,
                                      const VectorType     &u) const
  {
    // the residual rows are minus the forces on the bodies: the forces on
    // the obstacle
    const auto moment = [&](const types::global_dof_index row,
                            const double                  value,
                            Tensor<1, dim>               &force,
                            Tensor<1, 3>                 &torque) {
      const auto [node, d] = pair.dof_node.at(row);
      force[d] += value;
      const Tensor<1, dim> r =
        pair.secondary.position(node, u) - pair.trial_place.center;
      // r x (value e_d)
      Tensor<1, 3> r3, f3;
      for (unsigned int i = 0; i < dim; ++i)
        r3[i] = r[i];
      f3[d] = value;
      torque += cross_product_3d(r3, f3);
    };
    for (const auto &r : forces.rows)
      moment(r.row, r.value, pair.reaction.force, pair.reaction.torque);
    for (const auto &t : forces.tangential)
      moment(t.first,
             t.second,
             pair.reaction.friction_force,
             pair.reaction.friction_torque);
  }

  template <int dim>
  void
  ObstacleCoupling<dim>::add_to_sums(ProcessSums &sums)
  {
    for (auto &pair : pairs)
      if (pair.obstacle)
        {
          auto &r = pair.reaction;
          for (auto *t : {&r.force, &r.friction_force})
            sums.add_all(*t);
          for (auto *t : {&r.torque, &r.friction_torque})
            sums.add_all(*t);
        }
  }

  template <int dim>
  void
  ObstacleCoupling<dim>::commit(const ContactHistoryContext &)
  {
    last_normal_work = 0;
    for (auto &pair : pairs)
      if (pair.obstacle)
        {
          const auto power =
            [](const auto &place, const auto &force, const auto &torque) {
              return place.velocity * force + place.angular_velocity * torque;
            };
          const double dt = trial_time - committed_time;
          const auto  &r0 = pair.committed_reaction, &r1 = pair.reaction;
          const auto  &p0 = pair.committed_place, &p1 = pair.trial_place;
          const double step_work =
            -dt / 2 *
            (power(p0, r0.force, r0.torque) + power(p1, r1.force, r1.torque));
          const double step_friction_work =
            -dt / 2 *
            (power(p0, r0.friction_force, r0.friction_torque) +
             power(p1, r1.friction_force, r1.friction_torque));
          work_done += step_work;
          friction_work_done += step_friction_work;
          last_normal_work += step_work - step_friction_work;
          pair.committed_reaction = pair.reaction;
        }
  }

  template <int dim>
  void
  ObstacleCoupling<dim>::save(CheckpointData &data,
                              const ContactHistoryContext &) const
  {
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const auto         &pair = pairs[p];
        const std::string   key  = contact_pair_key(p);
        std::vector<double> reaction;
        const auto         &r = pair.committed_reaction;
        for (const auto *t : {&r.force, &r.friction_force})
          reaction.insert(reaction.end(), t->begin_raw(), t->end_raw());
        for (const auto *t : {&r.torque, &r.friction_torque})
          reaction.insert(reaction.end(), t->begin_raw(), t->end_raw());
        data.set(key + "reaction", reaction);
      }
    data.set("contact/obstacle work",
             {work_done, friction_work_done, last_normal_work});
  }

  template <int dim>
  void
  ObstacleCoupling<dim>::load(const CheckpointData        &data,
                              const ContactHistoryContext &)
  {
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        auto             &pair = pairs[p];
        const std::string key  = contact_pair_key(p);
        // (the tangent axes follow from the reference surface: an older
        // checkpoint's entry 'tangent axis' is not read)
        const auto &reaction = data.get(key + "reaction", 2 * dim + 6);
        auto       &r        = pair.committed_reaction;
        auto        x        = reaction.begin();
        for (auto *t : {&r.force, &r.friction_force})
          {
            std::copy(x, x + dim, t->begin_raw());
            x += dim;
          }
        for (auto *t : {&r.torque, &r.friction_torque})
          {
            std::copy(x, x + 3, t->begin_raw());
            x += 3;
          }
      }
    const auto &obstacle = data.get("contact/obstacle work", 3);
    work_done            = obstacle[0];
    friction_work_done   = obstacle[1];
    last_normal_work     = obstacle[2];
  }

  template <int dim>
  void
  ObstacleCoupling<dim>::add_columns(std::vector<std::string> &columns) const
  {
    // per obstacle: the reaction on it and the work it did on the bodies
    for (const auto &obstacle : contact.obstacles)
      {
        for (unsigned int d = 0; d < dim; ++d)
          columns.emplace_back(obstacle.name + "_force_" + "xyz"[d]);
        if (dim == 2)
          columns.emplace_back(obstacle.name + "_torque");
        else
          for (unsigned int d = 0; d < 3; ++d)
            columns.emplace_back(obstacle.name + "_torque_" + "xyz"[d]);
      }
    if (!contact.obstacles.empty())
      columns.emplace_back("obstacle_work");
  }

  template <int dim>
  void
  ObstacleCoupling<dim>::add_statistics(std::vector<double> &values) const
  {
    for (unsigned int k = 0; k < contact.obstacles.size(); ++k)
      {
        Tensor<1, dim> force;
        Tensor<1, 3>   torque;
        for (unsigned int p = 0; p < pairs.size(); ++p)
          if (contact.pairs[p].obstacle == int(k))
            {
              force += pairs[p].reaction.force;
              torque += pairs[p].reaction.torque;
            }
        values.insert(values.end(), force.begin_raw(), force.end_raw());
        if (dim == 2)
          values.push_back(torque[2]);
        else
          values.insert(values.end(), torque.begin_raw(), torque.end_raw());
      }
    if (!contact.obstacles.empty())
      values.push_back(work_done);
  }

  template class ObstacleCoupling<2>;
  template class ObstacleCoupling<3>;
} // namespace ContactDynamics

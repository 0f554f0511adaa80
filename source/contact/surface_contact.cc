// SurfaceContact: the setup of the pairs, the mesh change, the commit of a step
// and the statistics. The other concerns of the class have files of their
// own: surface_contact_complementarity.cc (the conditions and their assembly),
// _search.cc (swept search and sparsity), _hanging.cc (hanging surface
// nodes), _obstacle.cc (rigid obstacles), _checkpoint.cc and _check*.cc (the
// penetration checks per dimension).
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <contact_dynamics/contact/capture_count.h>
#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/contact/face_passage.h>
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <memory>
#include <set>
#include <sstream>

namespace ContactDynamics
{
  template <int dim>
  SurfaceContact<dim>::SurfaceContact(
    const ContactParameters         &contact,
    const ComplementarityParameters &complementarity)
    : contact(contact)
    , complementarity(complementarity)
    , obstacles(pairs, this->contact)
    , node_history(pairs, this->complementarity, comm)
    , search(
        pairs,
        comm,
        [this](const PairData &pair) {
          return n_patches(pair);
        },
        [this](const PairData &pair, const VectorType &u) {
          // every patch may meet an obstacle
          return pair.obstacle ?
                   std::vector<std::vector<unsigned int>>(n_patches(pair),
                                                          {0}) :
                   compute_candidates(pair, u, 2.0);
        })
  {
    for (ContactHistoryOwner *owner :
         std::initializer_list<ContactHistoryOwner *>{&work,
                                                      &obstacles,
                                                      &node_history,
                                                      &search})
      history.add(*owner);
    history.add(std::make_unique<CaptureCount<dim>>(pairs));
    using Stabilization = ComplementarityParameters::Stabilization;
    AssertThrow(
      !complementarity.capture_at_position ||
        complementarity.stabilization == Stabilization::persistency ||
        complementarity.stabilization == Stabilization::velocity_update,
      ExcMessage(
        std::string("Contact/") +
        (contact.formulation == ContactParameters::Formulation::mortar ?
           "Mortar" :
           "Node to segment") +
        "/Capture = position applies to Stabilization = "
        "persistency or velocity update only (it sets how a held "
        "node starts): set Capture = rate, or change that "
        "subsection's Stabilization."));
  }

  template <int dim>
  std::vector<std::string>
  SurfaceContact<dim>::extra_component_names() const
  {
    std::vector<std::string> names{"contact_pressure", "tangential_traction"};
    names.resize(dim, "tangential_traction_2");
    return names;
  }

  template <int dim>
  std::vector<types::boundary_id>
  SurfaceContact<dim>::secondary_boundary_ids() const
  {
    std::vector<types::boundary_id> ids;
    for (const ContactPair &pair : contact.pairs)
      ids.insert(ids.end(), pair.secondary.begin(), pair.secondary.end());
    return ids;
  }

  template <int dim>
  void
  SurfaceContact<dim>::setup(const DoFHandler<dim>   &dof_handler,
                             const Mapping<dim, dim> &mapping)
  {
    cell_mapping = &mapping;
    comm         = dof_handler.get_communicator();
    owned_dofs   = dof_handler.locally_owned_dofs();
    pairs.clear();
    pairs.resize(contact.pairs.size());
    std::set<types::global_dof_index> secondary_normal;
    friction = false;
    for (unsigned int p = 0; p < contact.pairs.size(); ++p)
      build_pair(p, dof_handler, secondary_normal);
    {
      std::set<types::global_dof_index> surface;
      for (const auto &pair : pairs)
        for (const auto *side : {&pair.secondary, &pair.primary})
          for (const auto &node_dofs : side->dofs)
            surface.insert(node_dofs.begin(), node_dofs.end());
      hanging.collect(dof_handler, surface, owned_dofs);
    }
    for (auto &pair : pairs)
      {
        pair.hanging_parents = hanging.node_parents(pair.secondary, dim);
        if constexpr (dim == 3)
          pair.primary_edge_subdivisions =
            hanging.edge_subdivisions(pair.primary);
        distribute(pair);
      }
    normal_multiplier_dofs.assign(secondary_normal.begin(),
                                  secondary_normal.end());
    {
      std::vector<std::array<const ContactSurface<dim> *, 2>> surfaces;
      for (const auto &pair : pairs)
        surfaces.push_back({{&pair.secondary, &pair.primary}});
      check_contact_setup(contact,
                          surfaces,
                          complementarity.capture_tolerance,
                          dof_handler.get_triangulation());
    }

    // every other multiplier unknown is held at zero (frictionless)
    other_multiplier_dofs.clear();
    std::vector<bool> mask(2 * dim, false);
    for (unsigned int c = dim; c < 2 * dim; ++c)
      mask[c] = true;
    // (every process needs the constraints of the dofs it touches)
    for (const auto i :
         union_over_processes(DoFTools::extract_dofs(dof_handler,
                                                     ComponentMask(mask)),
                              comm))
      if (secondary_normal.count(i) == 0)
        other_multiplier_dofs.push_back(i);

    // the contact forces act on the displacements of both surfaces
    std::set<types::global_dof_index> surface_displacements;
    for (auto &pair : pairs)
      {
        for (const auto *surface : {&pair.secondary, &pair.primary})
          for (const auto &node_dofs : surface->dofs)
            for (unsigned int d = 0; d < dim; ++d)
              surface_displacements.insert(node_dofs[d]);
        pair.position = pair.secondary.reference;
      }
    work.reinit(owned_dofs,
                comm,
                {surface_displacements.begin(), surface_displacements.end()},
                friction);
  }

  template <int dim>
  void
  SurfaceContact<dim>::build_pair(
    const unsigned int                 p,
    const DoFHandler<dim>             &dof_handler,
    std::set<types::global_dof_index> &secondary_normal)
  {
    auto &pair = pairs[p];
    pair.index = p;
    pair.secondary.build(dof_handler,
                         contact.pairs[p].secondary,
                         2 * dim,
                         cell_mapping);
    if (contact.pairs[p].obstacle >= 0)
      obstacles.set_up(pair, contact.obstacles[contact.pairs[p].obstacle]);
    else
      pair.primary.build(dof_handler,
                         contact.pairs[p].primary,
                         dim,
                         cell_mapping);
    AssertThrow(pair.secondary.n_faces() > 0 &&
                  (pair.obstacle || pair.primary.n_faces() > 0),
                ExcMessage("The contact pair '" + contact.pairs[p].name +
                           "' has an empty surface."));
    pair.nodes.assign(pair.secondary.n_nodes(), NodeState());
    pair.friction_coefficient = contact.pairs[p].friction_coefficient;
    for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
      {
        secondary_normal.insert(pair.secondary.dofs[j][dim]);
        // the tangential multipliers are unknowns only with friction
        if (pair.friction_coefficient > 0)
          for (unsigned int c = dim + 1; c < 2 * dim; ++c)
            secondary_normal.insert(pair.secondary.dofs[j][c]);
      }
    friction = friction || pair.friction_coefficient > 0;
  }

  template <int dim>
  void
  SurfaceContact<dim>::distribute(PairData &pair) const
  {
    pair.owned_node.assign(pair.secondary.n_nodes(), false);
    for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
      pair.owned_node[j] = owned_dofs.is_element(pair.secondary.dofs[j][dim]);
    const unsigned int rank      = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks   = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int n_patches = this->n_patches(pair);
    pair.node_owner.assign(pair.secondary.n_nodes(), 0);
    for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
      if (pair.owned_node[j])
        pair.node_owner[j] = rank;
    if (n_ranks > 1)
      Utilities::MPI::sum(pair.node_owner, comm, pair.node_owner);
    pair.handled_patch.assign(n_patches, false);
    pair.assembled_patch.assign(n_patches, false);
    for (unsigned int e = 0; e < n_patches; ++e)
      {
        // (a hanging node's sums go to the nodes it follows)
        for (const unsigned int j : patch_nodes(pair, e))
          {
            pair.handled_patch[e] = pair.handled_patch[e] || pair.owned_node[j];
            for (const auto &parent : pair.hanging_parents[j])
              pair.handled_patch[e] =
                pair.handled_patch[e] || pair.owned_node[parent.first];
          }
        // consecutive patches (neighbours, mostly) to one process
        pair.assembled_patch[e] =
          (std::uint64_t(e) * n_ranks) / n_patches == rank;
      }
  }

  template <int dim>
  void
  SurfaceContact<dim>::add_constraints(
    AffineConstraints<double> &constraints) const
  {
    for (const auto i : other_multiplier_dofs)
      if (!constraints.is_constrained(i))
        constraints.add_line(i);
  }

  template <int dim>
  IndexSet
  SurfaceContact<dim>::surface_dofs() const
  {
    IndexSet dofs(owned_dofs.size());
    for (const auto &pair : pairs)
      for (const auto *surface : {&pair.secondary, &pair.primary})
        for (const auto &node_dofs : surface->dofs)
          dofs.add_indices(node_dofs.begin(), node_dofs.end());
    dofs.compress();
    return dofs;
  }

  template <int dim>
  std::vector<MultiplierGroup>
  SurfaceContact<dim>::multiplier_groups() const
  {
    // a node on a primary surface too carries other nodes' multipliers in
    // its rows: it cannot be eliminated node by node, so it is left out
    std::set<types::global_dof_index> primary;
    for (const auto &pair : pairs)
      for (const auto &node_dofs : pair.primary.dofs)
        primary.insert(node_dofs[0]);
    std::vector<MultiplierGroup>      groups;
    std::set<types::global_dof_index> seen;
    for (const auto &pair : pairs)
      for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
        if (pair.owned_node[j] && pair.hanging_parents[j].empty() &&
            primary.count(pair.secondary.dofs[j][0]) == 0 &&
            seen.insert(pair.secondary.dofs[j][dim]).second)
          {
            MultiplierGroup group;
            for (unsigned int d = 0; d < dim; ++d)
              group.displacements.push_back(pair.secondary.dofs[j][d]);
            group.multipliers.push_back(pair.secondary.dofs[j][dim]);
            if (pair.friction_coefficient > 0)
              for (unsigned int c = dim + 1; c < 2 * dim; ++c)
                group.multipliers.push_back(pair.secondary.dofs[j][c]);
            groups.push_back(std::move(group));
          }
    return groups;
  }

  template <int dim>
  unsigned int
  SurfaceContact<dim>::n_owned_nodes(const unsigned int pair) const
  {
    return std::count(pairs[pair].owned_node.begin(),
                      pairs[pair].owned_node.end(),
                      true);
  }

  template <int dim>
  std::vector<std::string>
  SurfaceContact<dim>::statistics_columns() const
  {
    std::vector<std::string> columns{"active_contact_nodes",
                                     "contact_force_x",
                                     "contact_force_y"};
    if (dim == 3)
      columns.emplace_back("contact_force_z");
    columns.emplace_back("contact_work");
    if (friction)
      for (const char *c :
           {"stick_nodes", "slip_nodes", "frictional_dissipation"})
        columns.emplace_back(c);
    obstacles.add_columns(columns);
    return columns;
  }

  template <int dim>
  std::vector<double>
  SurfaceContact<dim>::statistics() const
  {
    std::vector<double> values{double(n_active)};
    values.insert(values.end(), std::begin(total_force), std::end(total_force));
    values.push_back(work.work());
    if (friction)
      for (const double v :
           {double(n_stick), double(n_slip), dissipated_energy()})
        values.push_back(v);
    obstacles.add_statistics(values);
    return values;
  }

  namespace
  {
    // An obstacle must face its surface: at the node nearest to it the
    // obstacle's normal (towards the bodies) and the surface's outward
    // normal are opposed. Within 60 degrees of the same direction the
    // obstacle is behind the surface (a plane's Normal reversed, a
    // cylinder inside the body): refused, even touching nothing.
    template <int dim>
    void
    check_obstacle_side(const ContactPairData<dim> &pair,
                        const std::string          &name,
                        const VectorType           &u)
    {
      const auto  &s       = pair.secondary;
      double       nearest = std::numeric_limits<double>::infinity();
      unsigned int node    = 0;
      // (every process has every surface node's position: the same
      // verdict on all of them, whatever the partition)
      for (unsigned int j = 0; j < s.n_nodes(); ++j)
        {
          Tensor<1, dim> normal;
          const double   distance =
            pair.obstacle->signed_distance(pair.committed_place,
                                           Tensor<1, dim>(s.position(j, u)),
                                           normal);
          if (distance < nearest)
            {
              nearest = distance;
              node    = j;
            }
        }
      if (nearest == std::numeric_limits<double>::infinity())
        return;
      Tensor<1, dim> normal;
      pair.obstacle->signed_distance(pair.committed_place,
                                     Tensor<1, dim>(s.position(node, u)),
                                     normal);
      const double cosine = outward_normal(s, node, u) * normal;
      AssertThrow(cosine <= 0.5,
                  ExcMessage(
                    "The rigid obstacle of pair '" + name +
                    "' lies behind its surface at t = 0: at the node "
                    "nearest to it, at " +
                    coordinates(s.reference[node]) +
                    " in the reference configuration (distance " +
                    format_number(nearest) +
                    "), the obstacle's normal and the surface's outward "
                    "normal are " +
                    format_number(std::acos(std::min(1., cosine)) * 180 /
                                  numbers::PI) +
                    " degrees apart (facing each other: 180). A plane's "
                    "Normal must point to the body; a cylinder or sphere "
                    "must lie outside the body."));
    }

    // A radius the faces cannot resolve (the obstacle slips between the
    // nodes and quadrature points: a needle indents with no force), or so
    // large that |x - c| - R loses the gap to round-off (1e300 made it
    // inactive), is refused; the bounds from the surface's faces.
    template <int dim>
    void
    check_obstacle_radius(const ContactPairData<dim> &pair,
                          const std::string          &name,
                          const VectorType           &u)
    {
      const double radius = pair.obstacle->radius();
      const auto  &s      = pair.secondary;
      if (radius == 0 || s.faces.empty())
        return; // a plane
      double           smallest = std::numeric_limits<double>::infinity();
      BoundingBox<dim> all;
      for (unsigned int f = 0; f < s.faces.size(); ++f)
        {
          double     length = 0;
          const auto box    = s.face_box(f, u, length);
          smallest          = std::min(smallest, length);
          if (f == 0)
            all = box;
          else
            all.merge_with(box);
        }
      const double extent = all.get_boundary_points().first.distance(
        all.get_boundary_points().second);
      AssertThrow(radius >= 0.1 * smallest,
                  ExcMessage("Radius = " + format_number(radius) +
                             " of the rigid obstacle of pair '" + name +
                             "' is below a tenth of the smallest face of "
                             "its surface (" +
                             format_number(smallest) +
                             "): the faces cannot resolve it (it would sink "
                             "between the nodes with no force). Refine the "
                             "surface or give a larger Radius."));
      AssertThrow(radius <= 1e6 * extent,
                  ExcMessage("Radius = " + format_number(radius) +
                             " of the rigid obstacle of pair '" + name +
                             "' is more than 1e6 times the size of its "
                             "surface (" +
                             format_number(extent) +
                             "): its gaps would be lost to round-off. Use "
                             "Shape = plane."));
    }

    // How deep each node of a meshed pair lies in the other body at t = 0,
    // by its own distance behind the nearest face it projects onto: a
    // secondary node behind the primary faces its patches found, and the
    // nodes of those faces behind the secondary faces around it (a primary
    // corner between two secondary nodes). The weighted gap (dual basis
    // functions change sign) is negative under a curved surface over
    // coarse faces that touches nothing (hertz_adaptive at factor 0.2): it
    // counts only for a node that projects onto none of the faces.
    template <int dim, typename Report>
    void
    meshed_pair_depths(const ContactPairData<dim>                &pair,
                       const std::vector<std::set<unsigned int>> &faces,
                       const VectorType                          &u,
                       const Report                              &report)
    {
      const auto &s = pair.secondary, &p = pair.primary;
      for (unsigned int j = 0; j < s.n_nodes(); ++j)
        {
          double depth = -pair.nodes[j].normalized_gap();
          if (!faces[j].empty())
            {
              const double own =
                depth_behind_surface(p, faces[j], s.position(j, u), u);
              if (!std::isnan(own))
                depth = own;
              const std::set<unsigned int> around(s.node_faces[j].begin(),
                                                  s.node_faces[j].end());
              for (const unsigned int f : faces[j])
                for (const unsigned int k : p.faces[f])
                  {
                    const double d =
                      depth_behind_surface(s, around, p.position(k, u), u);
                    if (!std::isnan(d))
                      report(d, "primary", p.reference[k]);
                  }
            }
          else if (!pair.owned_node[j])
            continue; // its owner judges it
          report(depth, "secondary", s.reference[j]);
        }
    }
  } // namespace

  template <int dim>
  void
  SurfaceContact<dim>::check_initial_state(const VectorType &u,
                                           std::ostream     &log) const
  {
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (pairs[p].obstacle)
        check_obstacle_radius(pairs[p], contact.pairs[p].name, u);
    double       worst = 0;
    unsigned int pair  = 0;
    std::string  node;
    const auto   deeper = [&](const double       depth,
                            const unsigned int p,
                            const char        *side,
                            const Point<dim>  &reference) {
      if (depth > worst)
        {
          worst = depth;
          pair  = p;
          node  = std::string(side) + " node at " + coordinates(reference);
        }
    };
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const auto &s = pairs[p].secondary;
        if (pairs[p].obstacle)
          for (unsigned int j = 0; j < s.n_nodes(); ++j)
            {
              // its own signed distance (every node on every process, as
              // check_obstacle_side()): the search finds no gap for a node
              // deep inside, and a weighted gap (dual basis functions
              // change sign) is negative under a curved obstacle over
              // coarse faces that touches nothing
              Tensor<1, dim> x(s.reference[j]), normal;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] += u(s.dofs[j][d]);
              deeper(
                -pairs[p].obstacle->signed_distance(pairs[p].committed_place,
                                                    x,
                                                    normal),
                p,
                "the",
                s.reference[j]);
            }
        else
          meshed_pair_depths(pairs[p],
                             candidate_faces(pairs[p]),
                             u,
                             [&](const double      depth,
                                 const char       *side,
                                 const Point<dim> &reference) {
                               deeper(depth, p, side, reference);
                             });
      }
    if (worst > complementarity.capture_tolerance)
      report_initial_overlap(worst, pair, node, log);
    const std::string found = caveats();
    if (!found.empty())
      log << "Warning: " << found << std::endl;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (pairs[p].obstacle)
        check_obstacle_side(pairs[p], contact.pairs[p].name, u);
  }

  template <int dim>
  void
  SurfaceContact<dim>::report_initial_overlap(const double       worst,
                                              const unsigned int pair,
                                              const std::string &node,
                                              std::ostream      &log) const
  {
    std::ostringstream where;
    if (pairs[pair].obstacle)
      where << "A node of pair '" << contact.pairs[pair].name
            << "' lies inside the rigid obstacle at t = 0, by " << worst << " ("
            << node << " in the reference configuration; Capture tolerance = "
            << complementarity.capture_tolerance
            << "; a plane's Normal must point to the body, a cylinder or "
               "sphere must lie outside it)";
    else
      where << "The bodies overlap at t = 0 by up to " << worst << " (pair '"
            << contact.pairs[pair].name << "', " << node
            << " in the reference configuration; Capture tolerance = "
            << complementarity.capture_tolerance << ")";
    AssertThrow(contact.allow_initial_penetration,
                ExcMessage(where.str() +
                           ". Pushing them apart would create energy. Move "
                           "them apart (a body's Initial displacement, "
                           "the mesh), or set Contact/Initial penetration = "
                           "allow to let the contact push them apart."));
    if (is_root(comm))
      log << "Warning: " << where.str()
          << "; Contact/Initial penetration = allow: the contact pushes them "
             "apart, and the energy this creates appears in contact_work."
          << std::endl;
  }

  template <int dim>
  void
  SurfaceContact<dim>::start_step()
  {
    history.start_attempt({});
  }

  template <int dim>
  void
  SurfaceContact<dim>::commit_step(const VectorType &u,
                                   const VectorType &old_u,
                                   const bool        reevaluation)
  {
    ContactHistoryContext context;
    context.u            = &u;
    context.old_u        = &old_u;
    context.reevaluation = reevaluation;
    history.commit(context);
  }

  template <int dim>
  void
  SurfaceContact<dim>::remesh(const DoFHandler<dim>   &dof_handler,
                              const Mapping<dim, dim> &mapping)
  {
    // (the work and dissipation done so far carry over)
    setup(dof_handler, mapping);
    history.transfer({});
  }

  template <int dim>
  std::vector<VectorType *>
  SurfaceContact<dim>::history_vectors()
  {
    return history.vectors();
  }

  template <int dim>
  void
  SurfaceContact<dim>::save_history(CheckpointData &data) const
  {
    history.save(data, {});
  }

  template <int dim>
  void
  SurfaceContact<dim>::load_history(const CheckpointData &data,
                                    const VectorType     &u)
  {
    const auto            maps = saved_node_map(data);
    ContactHistoryContext context;
    context.u         = &u;
    context.node_maps = &maps;
    history.load(data, context);
  }

  template <int dim>
  unsigned int
  SurfaceContact<dim>::n_extra_components() const
  {
    return dim;
  }

  template <int dim>
  unsigned int
  SurfaceContact<dim>::n_owned_contact_nodes() const
  {
    unsigned int n = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      n += n_owned_nodes(p);
    return n;
  }

  template <int dim>
  unsigned int
  SurfaceContact<dim>::n_active_nodes() const
  {
    return n_active;
  }

  template <int dim>
  const std::vector<types::global_dof_index> &
  SurfaceContact<dim>::multiplier_dofs() const
  {
    return normal_multiplier_dofs;
  }

  template <int dim>
  double
  SurfaceContact<dim>::obstacle_work() const
  {
    return obstacles.work();
  }

  template <int dim>
  double
  SurfaceContact<dim>::contact_work() const
  {
    return work.work();
  }

  template <int dim>
  double
  SurfaceContact<dim>::velocity_update_request() const
  {
    // (not the normal work of a moving obstacle: that is external work)
    return complementarity.stabilization == Stabilization::velocity_update ?
             work.normal_step_work() - obstacles.normal_step_work() :
             0.;
  }

  template <int dim>
  const VectorType *
  SurfaceContact<dim>::velocity_update_force() const
  {
    return &work.step_normal_force();
  }

  template <int dim>
  void
  SurfaceContact<dim>::add_velocity_update_work(const double work_done)
  {
    work.add_impulse_work(work_done);
  }

  template <int dim>
  double
  SurfaceContact<dim>::dissipated_energy() const
  {
    return work.dissipation() + obstacles.friction_work();
  }

  template <int dim>
  std::vector<std::pair<const VectorType *, std::string>>
  SurfaceContact<dim>::nodal_output_fields() const
  {
    std::vector<std::pair<const VectorType *, std::string>> fields{
      {&node_history.gap_field, "normal_gap"}};
    if (friction)
      {
        fields.emplace_back(&node_history.slip_field[0], "slip_rate");
        if (dim == 3)
          fields.emplace_back(&node_history.slip_field[1], "slip_rate_2");
      }
    return fields;
  }

  template <int dim>
  const std::vector<ContactNodeState> &
  SurfaceContact<dim>::node_states(const unsigned int pair) const
  {
    return pairs[pair].nodes;
  }

  template <int dim>
  const ContactSurface<dim> &
  SurfaceContact<dim>::secondary_surface(const unsigned int pair) const
  {
    return pairs[pair].secondary;
  }

  template <int dim>
  const ContactSurface<dim> &
  SurfaceContact<dim>::primary_surface(const unsigned int pair) const
  {
    return pairs[pair].primary;
  }

  template <int dim>
  unsigned int
  SurfaceContact<dim>::n_pairs() const
  {
    return pairs.size();
  }

  template <int dim>
  SecondaryNodes<dim>
  SurfaceContact<dim>::secondary_nodes(const unsigned int pair) const
  {
    SecondaryNodes<dim> nodes{pairs[pair].secondary.reference,
                              pairs[pair].position,
                              pairs[pair].nodes};
    for (const ContactHistoryOwner *owner : history.all())
      for (auto &column : owner->node_columns(pair))
        nodes.columns.push_back(std::move(column));
    return nodes;
  }

  template <int dim>
  const std::vector<std::vector<double>> &
  SurfaceContact<dim>::monitored_points() const
  {
    return contact.monitored_points;
  }

  template class SurfaceContact<2>;
  template class SurfaceContact<3>;
} // namespace ContactDynamics

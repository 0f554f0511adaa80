#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <contact_dynamics/contact/closest_point_3d.h>
#include <contact_dynamics/contact/contact_search.h>
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>

namespace ContactDynamics
{
  namespace
  {
    // What the patches add up at a node j of a pair
    template <typename PairData>
    std::vector<LinearizedValue *>
    node_sums(PairData &pair, const unsigned int j)
    {
      std::vector<LinearizedValue *> sums{&pair.gap[j],
                                          &pair.weight[j],
                                          &pair.gap_rate[j]};
      for (auto &v : pair.slip_rate[j])
        sums.push_back(&v);
      return sums;
    }

    // the two-valued selections parse into bools
    using Stabilization = ComplementarityParameters::Stabilization;
    const Selection<Stabilization> stabilization_names{
      {Stabilization::persistency, "persistency"},
      {Stabilization::velocity_persistency, "velocity persistency"},
      {Stabilization::velocity_update, "velocity update"},
      {Stabilization::none, "none"}};
    const Selection<bool> jacobian_names{{true, "exact"},
                                         {false, "approximate"}};

    // 2-D cross product
    template <int dim>
    double
    cross(const Tensor<1, dim> &a, const Tensor<1, dim> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    // A point moves linearly from x0 to x1 during the step, a face from
    // (a0, b0) to (a1, b1), all ends linearly. True if the point passes
    // through the face (not only its line) from the outer side (the side
    // of the normal, the tangent b - a turned clockwise) to the inner side.
    template <int dim>
    bool
    crosses_face(const Point<dim> &x0,
                 const Point<dim> &x1,
                 const Point<dim> &a0,
                 const Point<dim> &a1,
                 const Point<dim> &b0,
                 const Point<dim> &b1)
    {
      // h(s) = n(s).(x(s) - a(s)) |t(s)| = cross(r(s), t(s)) is quadratic
      // in s, with r = x - a, t = b - a
      const Tensor<1, dim> r0 = x0 - a0, dr = (x1 - a1) - r0;
      const Tensor<1, dim> t0 = b0 - a0, dt = (b1 - a1) - t0;
      const double         c0 = cross(r0, t0);
      const double         c1 = cross(r0, dt) + cross(dr, t0);
      const double         c2 = cross(dr, dt);
      if (!(c0 >= 0 && c0 + c1 + c2 < 0))
        return false;
      std::vector<double> roots;
      if (c2 == 0)
        roots.push_back(-c0 / c1); // c1 != 0: h changes sign
      else
        {
          const double discriminant = c1 * c1 - 4 * c2 * c0;
          if (discriminant < 0)
            return false;
          const double q =
            -0.5 * (c1 + (c1 >= 0 ? 1. : -1.) * std::sqrt(discriminant));
          roots.push_back(q / c2);
          if (q != 0)
            roots.push_back(c0 / q);
        }
      for (const double s : roots)
        if (s >= 0 && s <= 1)
          {
            const Tensor<1, dim> r = r0 + s * dr, t = t0 + s * dt;
            const double         xi = r * t / (t * t);
            if (xi >= -1e-10 && xi <= 1 + 1e-10)
              return true;
          }
      return false;
    }

    // "(x, y)" or "(x, y, z)"
    template <int dim>
    std::string
    coordinates(const Point<dim> &x)
    {
      std::ostringstream out;
      out << '(';
      for (unsigned int d = 0; d < dim; ++d)
        out << (d > 0 ? ", " : "") << x[d];
      out << ')';
      return out.str();
    }

    std::array<ClippingGeometry::Vec3<double>, 4>
    face_nodes(const ContactSurface<3> &surface,
               const unsigned int       face,
               const VectorType        &u)
    {
      std::array<ClippingGeometry::Vec3<double>, 4> x;
      for (unsigned int a = 0; a < 4; ++a)
        x[a] = surface.position(surface.faces[face][a], u);
      return x;
    }

    Point<3>
    face_center(const ContactSurface<3> &surface,
                const unsigned int       face,
                const VectorType        &u)
    {
      return Point<3>(
        ClippingGeometry::interpolate(face_nodes(surface, face, u), 0.5, 0.5));
    }

    // 3-D: how far the point x1 (x0 at the last step) lies behind the
    // bilinear face at the state u (committed_u), if it projects onto the
    // face at both states and was in front of it before; else 0. (The
    // states at the ends of the step, not the swept path of 2-D.)
    double
    depth_behind_face(const ContactSurface<3> &surface,
                      const unsigned int       face,
                      const Point<3>          &x0,
                      const Point<3>          &x1,
                      const VectorType        &committed_u,
                      const VectorType        &u)
    {
      using namespace ClippingGeometry;
      double signed_distance[2];
      for (unsigned int k = 0; k < 2; ++k)
        {
          const auto   x = face_nodes(surface, face, k == 0 ? committed_u : u);
          const auto  &p = k == 0 ? x0 : x1;
          double       xi, eta;
          const double margin = 1e-10;
          if (!closest_point(x, p, xi, eta) || xi < -margin || eta < -margin ||
              xi > 1 + margin || eta > 1 + margin)
            return 0;
          const auto   t = tangents(x, xi, eta);
          Vec3<double> n = ClippingGeometry::cross(t[0], t[1]);
          n /= norm(n);
          signed_distance[k] = (p - interpolate(x, xi, eta)) * n;
        }
      return signed_distance[0] >= 0 && signed_distance[1] < 0 ?
               -signed_distance[1] :
               0.;
    }
  } // namespace

  void
  ComplementarityParameters::declare_parameters(
    ParameterHandler                &prm,
    const ComplementarityParameters &defaults)
  {
    prm.declare_entry("c_n",
                      default_text(defaults.c_n),
                      Patterns::Double(1e-300),
                      "Complementarity constant c_n > 0 in C_j = lambda_j - "
                      "max(0, lambda_j - c_n g_j). It changes the Newton "
                      "path, not the solution; pick it within a few orders "
                      "of magnitude of E / h (stress / length).");
    prm.declare_entry("Normalize c_n",
                      default_text(defaults.normalize_c_n),
                      Patterns::Bool(),
                      "Mortar: divide the weighted gap by the nodal weight "
                      "integral(N_j) over the covered segments, so that c_n "
                      "does not depend on the mesh size (units stress / "
                      "length). The node-to-segment gap is a length already.");
    prm.declare_entry(
      "Stabilization",
      stabilization_names.name(defaults.stabilization),
      stabilization_names.pattern(),
      "What keeps contact from creating energy. 'persistency': a node in "
      "contact at the end of the previous step (gap <= Capture tolerance) "
      "enforces a zero Newmark rate of its normalized weighted gap, "
      "gdot_{n+1} = gamma/(beta dt) (g_{n+1} - g_n) + (terms of step n), "
      "with g the gap of the whole discretization (moving segments, "
      "rotating normals, changing Jacobians), so a held penetration stays "
      "constant to solver tolerance and frictionless contact does no work "
      "up to the time discretization. In long curved sliding it needs "
      "Newmark gamma > 1/2 (e.g. 0.55): with the trapezoidal rule the held "
      "multipliers' step-to-step alternation is undamped and grows. "
      "'velocity persistency': the paper's velocity-level condition -int "
      "psi (v_s - v_p).n = 0, exact on flat surfaces only (drift on curved "
      "sliding ones). 'velocity update': as 'persistency', then after each "
      "step one factor on the free velocities of the bodies the contact "
      "acted on returns the step's normal contact work to kinetic energy "
      "(a projection after Hairer, Lubich and Wanner, IV.4): impacts of "
      "free elastic bodies keep their energy exactly; it changes momentum, "
      "is worse than 'persistency' with Rayleigh damping and at the "
      "lift-off of driven bodies (chatter), and stops the bodies when they "
      "carry less kinetic energy than the work to return (doc/contact.md). "
      "'none': the gap is enforced at every step ('static').");
    prm.declare_entry("Capture tolerance",
                      default_text(defaults.capture_tolerance),
                      Patterns::Double(0),
                      "A node whose (normalized) gap, in length units, is at "
                      "most this value at the end of a step counts as in "
                      "contact for the persistency condition of the next "
                      "step (>= 0, at most a tenth of the shortest face of "
                      "the contact surfaces).");
    prm.declare_entry("c_t",
                      default_text(defaults.c_t),
                      Patterns::Double(1e-300),
                      "Friction complementarity constant c_t > 0 (paper "
                      "equation 8): decides stick or slip from lambda_t + c_t "
                      "v_t with the (normalized) relative tangential velocity "
                      "v_t; like c_n it changes the Newton path, not the "
                      "solution. Units stress x time / length; c_n dt is a "
                      "good start.");
    prm.declare_entry("Jacobian",
                      jacobian_names.name(defaults.exact_jacobian),
                      jacobian_names.pattern(),
                      "'exact': automatic differentiation through normals, "
                      "projections and segment end points. 'approximate': "
                      "those geometric derivatives are dropped, as in the "
                      "paper's code (more Newton iterations).");
  }

  void
  ComplementarityParameters::parse_parameters(ParameterHandler &prm)
  {
    c_n               = prm.get_double("c_n");
    normalize_c_n     = prm.get_bool("Normalize c_n");
    stabilization     = stabilization_names.value(prm.get("Stabilization"));
    capture_tolerance = prm.get_double("Capture tolerance");
    exact_jacobian    = jacobian_names.value(prm.get("Jacobian"));
    c_t               = prm.get_double("c_t");
  }



  template <int dim>
  SurfaceContact<dim>::SurfaceContact(
    const ContactParameters         &contact,
    const ComplementarityParameters &complementarity)
    : contact(contact)
    , complementarity(complementarity)
  {}

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
  SurfaceContact<dim>::setup(const DoFHandler<dim> &dof_handler)
  {
    comm       = dof_handler.get_communicator();
    owned_dofs = dof_handler.locally_owned_dofs();
    pairs.clear();
    pairs.resize(contact.pairs.size());
    std::set<types::global_dof_index> secondary_normal;
    friction = false;
    for (unsigned int p = 0; p < contact.pairs.size(); ++p)
      {
        auto &pair = pairs[p];
        pair.secondary.build(dof_handler, contact.pairs[p].secondary, 2 * dim);
        if (contact.pairs[p].obstacle >= 0)
          set_up_obstacle(pair, contact.obstacles[contact.pairs[p].obstacle]);
        else
          pair.primary.build(dof_handler, contact.pairs[p].primary, dim);
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
    collect_hanging_dofs(dof_handler);
    for (auto &pair : pairs)
      {
        pair.hanging_parents.assign(pair.secondary.n_nodes(), {});
        if (!hanging_dofs.empty())
          {
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
                                ExcMessage(
                                  "A hanging node of a contact surface at " +
                                  coordinates(pair.secondary.reference[j]) +
                                  " follows a node that is not on that "
                                  "surface."));
                    pair.hanging_parents[j].emplace_back(k->second, weight);
                  }
          }

        pair.owned_node.assign(pair.secondary.n_nodes(), false);
        for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
          pair.owned_node[j] =
            owned_dofs.is_element(pair.secondary.dofs[j][dim]);
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
                pair.handled_patch[e] =
                  pair.handled_patch[e] || pair.owned_node[j];
                for (const auto &parent : pair.hanging_parents[j])
                  pair.handled_patch[e] =
                    pair.handled_patch[e] || pair.owned_node[parent.first];
              }
            // consecutive patches (neighbours, mostly) to one process
            pair.assembled_patch[e] =
              (std::uint64_t(e) * n_ranks) / n_patches == rank;
          }
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
    // per line: its dof, the number of entries, then (dof, weight) pairs,
    // as doubles (exact below 2^53), from the owner of the dof
    std::vector<double> lines;
    for (const auto &line : hanging.get_lines())
      if (!line.entries.empty() && owned_dofs.is_element(line.index) &&
          surface.count(line.index) > 0)
        {
          lines.insert(lines.end(),
                       {double(line.index), double(line.entries.size())});
          for (const auto &[parent, weight] : line.entries)
            lines.insert(lines.end(), {double(parent), weight});
        }
    for (const auto &part : Utilities::MPI::all_gather(comm, lines))
      for (auto x = part.begin(); x != part.end();)
        {
          auto      &entries = hanging_dofs[std::llround(*x++)];
          const long n       = std::lround(*x++);
          for (long k = 0; k < n; ++k, x += 2)
            entries.emplace_back(std::llround(x[0]), x[1]);
        }
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
          const auto   sums = node_sums(pair, j);
          const double own  = force_per_gap_sum(pair, j);
          for (const auto &[k, weight] : pair.hanging_parents[j])
            {
              const double factor = weight * own / force_per_gap_sum(pair, k);
              const auto   target = node_sums(pair, k);
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

  template <int dim>
  void
  SurfaceContact<dim>::remesh(const DoFHandler<dim> &dof_handler)
  {
    const double contact_work = work.work(), dissipation = work.dissipation();
    setup(dof_handler);
    work.carry_totals(contact_work, dissipation);
    // the vectors of the old mesh; the next update_candidates() takes its
    // state as the committed one
    committed_u.clear();
    gap_field.clear();
    for (auto &field : slip_field)
      field.clear();
    committed_is_next = true;
  }

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
  void
  SurfaceContact<dim>::set_up_obstacle(
    PairData                      &pair,
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
        // the axis least aligned with the obstacle's normal at the node
        Tensor<1, dim> normal;
        pair.obstacle->signed_distance(pair.committed_place,
                                       Tensor<1, dim>(s.reference[j]),
                                       normal);
        for (unsigned int d = 1; d < dim; ++d)
          if (std::abs(normal[d]) < std::abs(normal[pair.tangent_axis[j]]))
            pair.tangent_axis[j] = d;
      }
  }

  template <int dim>
  void
  SurfaceContact<dim>::set_times(const double committed, const double trial)
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
  std::vector<types::global_dof_index>
  SurfaceContact<dim>::obstacle_patch_unknowns(const PairData    &pair,
                                               const unsigned int patch) const
  {
    const auto                           nodes = patch_nodes(pair, patch);
    std::vector<types::global_dof_index> unknowns;
    for (const unsigned int n : nodes)
      for (unsigned int d = 0; d < dim; ++d)
        unknowns.push_back(pair.secondary.dofs[n][d]);
    for (unsigned int c = dim; c < 2 * dim; ++c)
      for (const unsigned int n : nodes)
        unknowns.push_back(pair.secondary.dofs[n][c]);
    return unknowns;
  }

  template <int dim>
  void
  SurfaceContact<dim>::add_reaction(PairData          &pair,
                                    const PatchForces &forces,
                                    const VectorType  &u) const
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
  SurfaceContact<dim>::add_constraints(
    AffineConstraints<double> &constraints) const
  {
    for (const auto i : other_multiplier_dofs)
      if (!constraints.is_constrained(i))
        constraints.add_line(i);
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
        box.merge_with(pair.primary.face_box(f, committed_u, committed_length));
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
    box.merge_with(patch_box(pair, patch, committed_u, committed_size));
    box.extend(margin_factor * std::max(size, committed_size));
    return box;
  }

  template <int dim>
  std::vector<std::vector<unsigned int>>
  SurfaceContact<dim>::obstacle_candidates(const PairData   &pair,
                                           const VectorType &u,
                                           const double margin_factor) const
  {
    // {0} for a patch whose swept box comes within its margin of the
    // obstacle at either time (the signed distance changes by at most the
    // distance between two points)
    std::vector<std::vector<unsigned int>> result(n_patches(pair));
    for (unsigned int p = 0; p < n_patches(pair); ++p)
      if (pair.handled_patch[p] || pair.assembled_patch[p])
        {
          const BoundingBox<dim> box =
            swept_patch_box(pair, p, u, margin_factor);
          const auto     corners = box.get_boundary_points();
          const double   reach   = corners.first.distance(corners.second) / 2;
          Tensor<1, dim> normal;
          for (const auto *place : {&pair.committed_place, &pair.trial_place})
            if (pair.obstacle->signed_distance(*place,
                                               Tensor<1, dim>(box.center()),
                                               normal) <= reach)
              result[p] = {0};
        }
    return result;
  }

  template <int dim>
  bool
  SurfaceContact<dim>::update_candidates(const VectorType &u)
  {
    if (gap_field.size() != u.size())
      {
        gap_field.reinit(owned_dofs, comm);
        for (auto &field : slip_field)
          field.reinit(owned_dofs, comm);
      }
    // before the first commit the committed state is the reference
    // configuration (as for PairData::position)
    if (committed_u.size() != u.size())
      committed_u.reinit(u);
    if (committed_is_next)
      committed_u = u;
    committed_is_next = false;
    bool rebuild      = false;
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
                if (const auto h = hanging_dofs.find(unknowns[i]);
                    h != hanging_dofs.end())
                  for (const auto &parent : h->second)
                    unknowns.push_back(parent.first);
              if (pair.assembled_patch[p])
                for (const auto row : unknowns)
                  for (const auto col : unknowns)
                    dsp.add(row, col);
              if (pair.handled_patch[p])
                for (const unsigned int n : patch_nodes(pair, p))
                  {
                    node_columns[n].insert(unknowns.begin(), unknowns.end());
                    for (const auto &parent : pair.hanging_parents[n])
                      node_columns[parent.first].insert(unknowns.begin(),
                                                        unknowns.end());
                  }
            }
        for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
          if (pair.owned_node[j])
            for (const auto col : node_columns[j])
              dsp.add(pair.secondary.dofs[j][dim], col);
      }
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
  void
  SurfaceContact<dim>::add_forces(const PatchForces  &forces,
                                  const LinearSystem &system)
  {
    // the force on a hanging node acts on the nodes it follows (C^T f)
    std::vector<std::pair<types::global_dof_index, double>> to(1);
    const auto targets = [&](const types::global_dof_index row)
      -> const std::vector<std::pair<types::global_dof_index, double>> & {
      if (!hanging_dofs.empty())
        if (const auto h = hanging_dofs.find(row); h != hanging_dofs.end())
          return h->second;
      to[0] = {row, 1.};
      return to;
    };
    for (const auto &r : forces.rows)
      for (const auto &[row, weight] : targets(r.row))
        {
          system.residual_full(row) += weight * r.value;
          work.add_force(row, weight * r.value);
          if (system.constraints.is_constrained(row))
            continue;
          system.residual(row) += weight * r.value;
          if (system.with_jacobian)
            add_row(system, row, r.derivatives, weight);
        }
    for (const auto &t : forces.tangential)
      for (const auto &[row, weight] : targets(t.first))
        work.add_friction_force(row, weight * t.second);
  }

  template <int dim>
  LinearizedValue
  SurfaceContact<dim>::held_gap_rate(PairData          &pair,
                                     const unsigned int j,
                                     const TrialState  &state) const
  {
    // the Newmark rate of the normalized gap g/w, from its committed value
    // and rates, times c_n dt; unnormalized: times w (c_n dt w gdot)
    NodeState   &node  = pair.nodes[j];
    const auto  &g     = pair.gap[j];
    const auto  &w     = pair.weight[j];
    const double ratio = g.value / w.value;
    const double c     = complementarity.c_n * state.dt;
    state.integrator.update(state.dt,
                            node.held_gap,
                            node.held_rate,
                            node.held_acceleration,
                            ratio,
                            node.gap_rate,
                            node.gap_acceleration);
    const double    scale = complementarity.normalize_c_n ? 1. : w.value;
    LinearizedValue rate;
    rate.value = c * scale * node.gap_rate;
    // d(g/w) = dg / w - g dw / w^2
    for (const auto &d : g.derivatives)
      rate.derivatives[d.first] += c * scale * state.c_v * d.second / w.value;
    for (const auto &d : w.derivatives)
      rate.derivatives[d.first] -=
        c * scale * state.c_v * ratio * d.second / w.value;
    if (!complementarity.normalize_c_n)
      for (const auto &d : w.derivatives)
        rate.derivatives[d.first] += c * node.gap_rate * d.second;
    return rate;
  }

  template <int dim>
  bool
  SurfaceContact<dim>::assemble_normal(PairData           &pair,
                                       const unsigned int  j,
                                       const TrialState   &state,
                                       const LinearSystem &system,
                                       LinearizedValue    &constraint)
  {
    // the complementarity condition, scaled by the node's reference weight
    // so that its row has force units
    NodeState                    &node   = pair.nodes[j];
    const types::global_dof_index row    = pair.secondary.dofs[j][dim];
    const double                  scale  = pair.secondary.reference_weight[j];
    const double                  lambda = state.u(row);
    node.pressure = lambda * traction_per_multiplier(pair, j, state.u);
    node.gap      = pair.gap[j].value;
    node.weight   = pair.weight[j].value;
    // a node counts once the formulation's coverage rule lets it
    node.projected = node.weight > minimum_coverage() * scale;

    // the constraint quantity c * g / w (or its rate) and its derivatives
    bool active = false;
    if (node.projected)
      {
        const bool normalize = complementarity.normalize_c_n;
        const bool held      = node.persistent && state.dynamic;
        const auto rates     = complementarity.stabilization;
        node.velocity_rate   = pair.gap_rate[j].value / node.weight;
        if (held && rates != Stabilization::velocity_persistency)
          constraint = held_gap_rate(pair, j, state);
        else
          {
            const bool velocity =
              held && rates == Stabilization::velocity_persistency;
            const LinearizedValue &g =
              velocity ? pair.gap_rate[j] : pair.gap[j];
            const double factor =
              complementarity.c_n * (velocity ? state.dt : 1.);
            const double w   = normalize ? node.weight : 1.;
            constraint.value = factor * g.value / w;
            for (const auto &d : g.derivatives)
              constraint.derivatives[d.first] += factor * d.second / w;
            if (normalize)
              for (const auto &d : pair.weight[j].derivatives)
                constraint.derivatives[d.first] -=
                  factor * g.value * d.second / (w * w);
            node.gap_rate         = node.velocity_rate;
            node.gap_acceleration = 0;
          }
        active = (lambda - constraint.value > 0);
      }
    node.active = active;
    n_active += active;
    if (system.constraints.is_constrained(row))
      return active;
    if (active)
      {
        system.residual(row) += scale * constraint.value;
        if (system.with_jacobian)
          add_row(system, row, constraint.derivatives, scale);
      }
    else
      {
        system.residual(row) += scale * lambda;
        if (system.with_jacobian)
          system.jacobian.add(row, row, scale);
      }
    return active;
  }

  template <int dim>
  void
  SurfaceContact<dim>::assemble_friction(PairData              &pair,
                                         const unsigned int     j,
                                         const bool             active,
                                         const LinearizedValue &constraint,
                                         const VectorType      &u,
                                         const LinearSystem    &system)
  {
    // Coulomb friction (paper equation 8) in its semi-smooth form, for the
    // vector lambda_t of the dim - 1 tangential multipliers: with
    // xi = lambda_n - c_n g (the normal argument) and s = lambda_t + c_t v,
    //   inactive:           lambda_t = 0
    //   stick (|s| < mu xi): v = 0 (written c_t v = 0)
    //   slip:               lambda_t - mu xi s / |s| = 0
    // (the slip direction from the trial traction s, as in Hueeber, Stadler
    // and Wohlmuth 2008; in 2-D s / |s| is its sign)
    constexpr unsigned int        n_t   = dim - 1;
    NodeState                    &node  = pair.nodes[j];
    const double                  scale = pair.secondary.reference_weight[j];
    const double                  mu    = pair.friction_coefficient;
    const types::global_dof_index normal_row = pair.secondary.dofs[j][dim];
    const double                  lambda_n   = u(normal_row);
    std::array<types::global_dof_index, n_t> rows;
    std::array<double, n_t>                  lambda_t;
    // normalized slip rates
    std::array<LinearizedValue, n_t> v;
    const double                     w =
      (complementarity.normalize_c_n && node.projected) ? node.weight : 1.;
    for (unsigned int a = 0; a < n_t; ++a)
      {
        rows[a]                     = pair.secondary.dofs[j][dim + 1 + a];
        lambda_t[a]                 = u(rows[a]);
        const LinearizedValue &slip = pair.slip_rate[j][a];
        v[a].value                  = slip.value / w;
        for (const auto &d : slip.derivatives)
          v[a].derivatives[d.first] += d.second / w;
        if (complementarity.normalize_c_n && node.projected)
          for (const auto &d : pair.weight[j].derivatives)
            v[a].derivatives[d.first] -= slip.value * d.second / (w * w);
        node.tangential[a] = lambda_t[a] * traction_per_multiplier(pair, j, u);
        node.slip_rate[a]  = v[a].value;
      }
    node.stick = false;
    if (system.constraints.is_constrained(rows[0]))
      return;

    const double            xi = lambda_n - constraint.value;
    std::array<double, n_t> trial;
    double                  trial_norm = 0;
    for (unsigned int a = 0; a < n_t; ++a)
      {
        trial[a] = lambda_t[a] + complementarity.c_t * v[a].value;
        trial_norm += trial[a] * trial[a];
      }
    trial_norm = std::sqrt(trial_norm);
    if (!active)
      {
        for (unsigned int a = 0; a < n_t; ++a)
          {
            system.residual(rows[a]) += scale * lambda_t[a];
            if (system.with_jacobian)
              system.jacobian.add(rows[a], rows[a], scale);
          }
        return;
      }
    // (|s| = 0 sticks: active means xi > 0, unless mu xi underflows)
    if (trial_norm < mu * xi || trial_norm == 0)
      {
        node.stick = true;
        ++n_stick;
        for (unsigned int a = 0; a < n_t; ++a)
          {
            system.residual(rows[a]) +=
              scale * complementarity.c_t * v[a].value;
            if (system.with_jacobian)
              add_row(system,
                      rows[a],
                      v[a].derivatives,
                      scale * complementarity.c_t);
          }
        return;
      }
    ++n_slip;
    // d(s / |s|)/ds = (I - e e^T) / |s|, e = s / |s|: zero in 2-D
    std::array<double, n_t> e;
    for (unsigned int a = 0; a < n_t; ++a)
      e[a] = trial[a] / trial_norm;
    for (unsigned int a = 0; a < n_t; ++a)
      {
        system.residual(rows[a]) += scale * (lambda_t[a] - mu * xi * e[a]);
        if (!system.with_jacobian)
          continue;
        std::map<types::global_dof_index, double> row;
        row[rows[a]] += 1.;
        row[normal_row] -= mu * e[a];
        for (const auto &d : constraint.derivatives)
          row[d.first] += mu * e[a] * d.second;
        if constexpr (dim == 3)
          for (unsigned int b = 0; b < n_t; ++b)
            {
              const double curvature =
                -mu * xi * ((a == b ? 1. : 0.) - e[a] * e[b]) / trial_norm;
              row[rows[b]] += curvature;
              for (const auto &d : v[b].derivatives)
                row[d.first] += curvature * complementarity.c_t * d.second;
            }
        add_row(system, rows[a], row, scale);
      }
  }

  template <int dim>
  void
  SurfaceContact<dim>::assemble(const TrialState                &state,
                                const AffineConstraints<double> &constraints,
                                const bool                       with_jacobian,
                                VectorType                      &residual,
                                MatrixType                      &jacobian,
                                VectorType                      &residual_full)
  {
    work.start_assembly();
    n_stick = n_slip = 0;
    n_active         = 0;
    std::fill(std::begin(total_force), std::end(total_force), 0.);
    for (auto &pair : pairs)
      pair.reaction = {};
    const LinearSystem system{constraints,
                              with_jacobian,
                              residual,
                              jacobian,
                              residual_full};
    // (every pair's sums exist before any patch can fail: the exchange
    // runs anyway)
    for (auto &pair : pairs)
      {
        const unsigned int n_nodes = pair.secondary.n_nodes();
        pair.gap.assign(n_nodes, LinearizedValue());
        pair.weight.assign(n_nodes, LinearizedValue());
        pair.gap_rate.assign(n_nodes, LinearizedValue());
        pair.slip_rate.assign(n_nodes, {});
      }
    run_collectively(
      comm,
      [&]() {
        for (auto &pair : pairs)
          {
            assemble_patches(pair, state, system);
            move_hanging_sums(pair);
          }
      },
      [&]() {
        for (auto &pair : pairs)
          exchange_node_sums(pair);
      });
    run_collectively(
      comm,
      [&]() {
        for (auto &pair : pairs)
          assemble_nodes(pair, state, system);
      },
      [&]() {
        finish_assembly(system);
      });
  }

  template <int dim>
  void
  SurfaceContact<dim>::assemble_patches(PairData           &pair,
                                        const TrialState   &state,
                                        const LinearSystem &system)
  {
    for (unsigned int p = 0; p < n_patches(pair); ++p)
      if (pair.assembled_patch[p])
        {
          PatchForces forces;
          if (!pair.obstacle)
            assemble_patch(pair, p, state, forces);
          else if (!pair.candidates[p].empty())
            {
              assemble_obstacle_patch(pair, p, state, forces);
              add_reaction(pair, forces, state.u);
            }
          add_forces(forces, system);
        }
  }

  template <int dim>
  void
  SurfaceContact<dim>::exchange_node_sums(PairData &pair) const
  {
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return;
    // per node: its index, then per quantity the value, the number of
    // derivatives and the (unknown, derivative) pairs, all as doubles
    // (exact for indices below 2^53)
    std::map<unsigned int, std::vector<double>> outgoing;
    for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
      if (!pair.owned_node[j])
        {
          const auto quantities = node_sums(pair, j);
          if (std::all_of(quantities.begin(), quantities.end(), [](auto *q) {
                return q->value == 0 && q->derivatives.empty();
              }))
            continue;
          auto &data = outgoing[pair.node_owner[j]];
          data.push_back(j);
          for (LinearizedValue *q : quantities)
            {
              data.push_back(q->value);
              data.push_back(q->derivatives.size());
              for (const auto &[i, d] : q->derivatives)
                data.insert(data.end(), {double(i), d});
              *q = LinearizedValue();
            }
        }
    for (const auto &[rank, data] :
         Utilities::MPI::some_to_some(comm, outgoing))
      for (auto x = data.begin(); x != data.end();)
        {
          const unsigned int j = std::lround(*x++);
          Assert(pair.owned_node[j], ExcInternalError());
          for (LinearizedValue *q : node_sums(pair, j))
            {
              q->value += *x++;
              const long n = std::lround(*x++);
              for (long k = 0; k < n; ++k, x += 2)
                q->derivatives[types::global_dof_index(std::llround(x[0]))] +=
                  x[1];
            }
        }
  }

  template <int dim>
  void
  SurfaceContact<dim>::assemble_nodes(PairData           &pair,
                                      const TrialState   &state,
                                      const LinearSystem &system)
  {
    for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
      if (pair.owned_node[j])
        {
          LinearizedValue constraint;
          const bool      active =
            assemble_normal(pair, j, state, system, constraint);
          // a constrained normal row has no friction row either
          if (pair.friction_coefficient > 0 &&
              !system.constraints.is_constrained(pair.secondary.dofs[j][dim]))
            assemble_friction(pair, j, active, constraint, state.u, system);
        }
  }

  template <int dim>
  void
  SurfaceContact<dim>::finish_assembly(const LinearSystem &system)
  {
    system.residual.compress(VectorOperation::add);
    system.residual_full.compress(VectorOperation::add);
    if (system.with_jacobian)
      system.jacobian.compress(VectorOperation::add);
    work.compress();
    const VectorType &force = work.trial_force();

    for (const auto &pair : pairs)
      for (const auto &node_dofs : pair.secondary.dofs)
        for (unsigned int d = 0; d < dim; ++d)
          if (owned_dofs.is_element(node_dofs[d]))
            total_force[d] -= force(node_dofs[d]);
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      {
        std::vector<double> sums(std::begin(total_force),
                                 std::end(total_force));
        sums.insert(sums.end(),
                    {double(n_active), double(n_stick), double(n_slip)});
        for (auto &pair : pairs)
          if (pair.obstacle)
            {
              auto &r = pair.reaction;
              for (auto *t : {&r.force, &r.friction_force})
                sums.insert(sums.end(), t->begin_raw(), t->end_raw());
              for (auto *t : {&r.torque, &r.friction_torque})
                sums.insert(sums.end(), t->begin_raw(), t->end_raw());
            }
        Utilities::MPI::sum(sums, comm, sums);
        std::copy(sums.begin(), sums.begin() + dim, std::begin(total_force));
        n_active = std::lround(sums[dim]);
        n_stick  = std::lround(sums[dim + 1]);
        n_slip   = std::lround(sums[dim + 2]);
        auto x   = sums.begin() + dim + 3;
        for (auto &pair : pairs)
          if (pair.obstacle)
            {
              auto &r = pair.reaction;
              for (auto *t : {&r.force, &r.friction_force})
                for (unsigned int d = 0; d < dim; ++d)
                  (*t)[d] = *x++;
              for (auto *t : {&r.torque, &r.friction_torque})
                for (unsigned int d = 0; d < 3; ++d)
                  (*t)[d] = *x++;
            }
        gather_node_states();
      }
  }

  template <int dim>
  void
  SurfaceContact<dim>::gather_node_states()
  {
    // each node's state comes from the process that owns it; a sum over
    // processes of the owned entries (zeros elsewhere) gathers them
    constexpr unsigned int n_fields = 10;
    std::vector<double>    data;
    for (const auto &pair : pairs)
      for (unsigned int j = 0; j < pair.nodes.size(); ++j)
        {
          const NodeState &n = pair.nodes[j];
          if (pair.owned_node[j])
            data.insert(data.end(),
                        {n.gap,
                         n.weight,
                         n.pressure,
                         n.tangential[0],
                         n.tangential[1],
                         n.slip_rate[0],
                         n.slip_rate[1],
                         double(n.projected),
                         double(n.active),
                         double(n.stick)});
          else
            data.resize(data.size() + n_fields, 0.);
        }
    Utilities::MPI::sum(data, comm, data);
    auto x = data.begin();
    for (auto &pair : pairs)
      for (auto &n : pair.nodes)
        {
          n.gap        = x[0];
          n.weight     = x[1];
          n.pressure   = x[2];
          n.tangential = {{x[3], x[4]}};
          n.slip_rate  = {{x[5], x[6]}};
          n.projected  = x[7] > 0.5;
          n.active     = x[8] > 0.5;
          n.stick      = x[9] > 0.5;
          x += n_fields;
        }
  }

  template <int dim>
  void
  SurfaceContact<dim>::commit_step(const VectorType &u, const VectorType &old_u)
  {
    work.commit(u, old_u);
    committed_u = u; // for the swept search of the next step
    // the obstacles' work on the bodies: minus the power of the reaction
    // on the obstacle's rigid motion, trapezoidal in time
    obstacle_normal_step_work = 0;
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
          obstacle_work_done += step_work;
          obstacle_friction_work += step_friction_work;
          obstacle_normal_step_work += step_work - step_friction_work;
          pair.committed_reaction = pair.reaction;
        }
    gap_field = 0;
    for (auto &field : slip_field)
      field = 0;
    for (auto &pair : pairs)
      for (unsigned int j = 0; j < pair.nodes.size(); ++j)
        {
          NodeState &node = pair.nodes[j];
          // a node held in contact through the step carries the Newmark
          // rates of its gap (zero); any other starts holding with the rate
          // of its velocities: the Newmark recursion of a gap that moves
          // freely (over the kinks of sliding faces) rings from step to step
          const bool held_in_contact = node.persistent && node.active;
          node.held_gap              = node.normalized_gap();
          node.held_rate             = !node.projected ? 0. :
                                       held_in_contact ? node.gap_rate :
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
                slip_field[a](pair.secondary.dofs[j][dim]) = node.slip_rate[a];
            }
          pair.position[j] = pair.secondary.position(j, u);
        }
    gap_field.compress(VectorOperation::insert);
    for (auto &field : slip_field)
      field.compress(VectorOperation::insert);
  }

  template <int dim>
  std::string
  SurfaceContact<dim>::check_step(const VectorType &u) const
  {
    // A node that the step's contact conditions did not hold back (see
    // doc/contact.md, "Search"): (1) not active at the converged state, yet
    // its straight path relative to a primary face passed through the face
    // from outside and ends more than `depth` behind it; or (2) projected
    // with a penetration beyond `own_depth`: a converged gap condition
    // leaves none, a held node none deeper than half a primary element.
    std::ostringstream failure;
    for (unsigned int p = 0; p < pairs.size() && failure.str().empty(); ++p)
      {
        const PairData &pair = pairs[p];
        const auto     &s    = pair.secondary;
        const auto     &f    = pair.primary;
        // the primary faces each node's patches found
        std::vector<std::set<unsigned int>> faces(s.n_nodes());
        for (unsigned int e = 0; e < n_patches(pair); ++e)
          if (pair.handled_patch[e])
            for (const unsigned int j : patch_nodes(pair, e))
              faces[j].insert(pair.candidates[e].begin(),
                              pair.candidates[e].end());
        for (unsigned int j = 0; j < s.n_nodes() && failure.str().empty(); ++j)
          {
            const NodeState &node = pair.nodes[j];
            if (!pair.owned_node[j])
              continue;
            // a hanging node is held with the nodes it follows, on average:
            // where one of them is in contact, it is judged by them
            if (std::any_of(pair.hanging_parents[j].begin(),
                            pair.hanging_parents[j].end(),
                            [&](const auto &parent) {
                              const NodeState &q = pair.nodes[parent.first];
                              return q.active || q.persistent;
                            }))
              continue;
            const Point<dim> x0    = s.position(j, committed_u);
            const Point<dim> x1    = s.position(j, u);
            const auto       where = [&]() -> std::ostream       &{
              return failure << "contact pair '" << contact.pairs[p].name
                             << "': the secondary node at " << coordinates(x1)
                             << " (reference " << coordinates(s.reference[j])
                             << ", at " << coordinates(x0)
                             << " at the last step) ";
            };
            // a held (persistent) node may sink by dt/2 times the approach
            // rate it had, but not by half the depth of the primary elements
            // it faces: deeper, the mesh no longer resolves the contact (a
            // node may pass a thin body and leave the search's reach)
            double element_depth = 1e300;
            if (pair.obstacle)
              {
                // the obstacle's size, at most the secondary elements'
                element_depth = pair.obstacle->depth();
                for (const unsigned int e : s.node_faces[j])
                  element_depth = std::min(element_depth, s.depth[e]);
              }
            else
              for (const unsigned int e : faces[j])
                element_depth = std::min(element_depth, f.depth[e]);
            const double own_depth =
              std::max(complementarity.capture_tolerance,
                       node.persistent ?
                         0.5 * element_depth :
                         1e-2 * 2 *
                           std::pow(s.reference_weight[j], 1. / (dim - 1)));
            if (node.projected && node.normalized_gap() < -own_depth)
              {
                where()
                  << "penetrates by " << -node.normalized_gap()
                  << (node.persistent ?
                        " while held, more than half the depth of the primary "
                        "elements (" :
                        " at its first contact, more than a converged "
                        "gap condition allows (")
                  << own_depth << ")";
                break;
              }
            // (a node held in this step enforces its gap rate: it may end
            // inactive behind a face while it separates, within the depth
            // above)
            // (a node behind an obstacle is projected: its gap says so)
            if (node.active || node.persistent || pair.obstacle)
              continue;
            if constexpr (dim == 3)
              {
                for (const unsigned int e : faces[j])
                  if (const double depth =
                        depth_behind_face(f, e, x0, x1, committed_u, u);
                      depth > std::max(complementarity.capture_tolerance,
                                       1e-2 * f.depth[e]))
                    {
                      where() << "went through the primary face with center "
                              << coordinates(face_center(f, e, u))
                              << " in this step and ends " << depth
                              << " behind it, but its contact condition is "
                                 "not active";
                      break;
                    }
                continue;
              }
            for (const unsigned int e : faces[j])
              {
                const unsigned int a = f.faces[e][0], b = f.faces[e][1];
                const Point<dim>   a1 = f.position(a, u), b1 = f.position(b, u);
                if (!crosses_face(x0,
                                  x1,
                                  f.position(a, committed_u),
                                  a1,
                                  f.position(b, committed_u),
                                  b1))
                  continue;
                const double length = a1.distance(b1);
                const double depth =
                  -cross(x1 - a1, b1 - a1) / std::max(length, 1e-300);
                if (depth <=
                    std::max(complementarity.capture_tolerance, 1e-2 * length))
                  continue;
                where() << "went through the primary face from (" << a1[0]
                        << ", " << a1[1] << ") to (" << b1[0] << ", " << b1[1]
                        << ") in this step and ends " << depth
                        << " behind it, but its contact condition is not "
                           "active";
                break;
              }
          }
      }
    std::string message = failure.str();
    if (!message.empty())
      message += "; the step is rejected and a smaller one tried";
    // the same decision on every process
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      for (const auto &m : Utilities::MPI::all_gather(comm, message))
        if (!m.empty())
          return m;
    return message;
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
      values.push_back(obstacle_work_done);
    return values;
  }

  template <int dim>
  void
  SurfaceContact<dim>::check_initial_state(std::ostream &log) const
  {
    double       worst = 0;
    unsigned int pair = 0, node = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int j = 0; j < pairs[p].nodes.size(); ++j)
        if (-pairs[p].nodes[j].normalized_gap() > worst)
          {
            worst = -pairs[p].nodes[j].normalized_gap();
            pair  = p;
            node  = j;
          }
    if (worst <= complementarity.capture_tolerance)
      return;
    std::ostringstream where;
    where << "The bodies overlap at t = 0 by up to " << worst << " (pair '"
          << contact.pairs[pair].name << "', secondary node at "
          << coordinates(pairs[pair].secondary.reference[node])
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

  namespace
  {
    // a node's state in a checkpoint: every field, in this order
    constexpr unsigned int n_saved_fields = 18;

    void
    pack(const ContactNodeState &n, double *x)
    {
      const double values[n_saved_fields] = {n.gap,
                                             n.weight,
                                             n.pressure,
                                             n.tangential[0],
                                             n.tangential[1],
                                             n.slip_rate[0],
                                             n.slip_rate[1],
                                             double(n.projected),
                                             double(n.active),
                                             double(n.stick),
                                             double(n.persistent),
                                             n.gap_rate,
                                             n.gap_acceleration,
                                             n.velocity_rate,
                                             n.held_gap,
                                             n.held_rate,
                                             n.held_acceleration,
                                             0.};
      std::copy(values, values + n_saved_fields, x);
    }

    void
    unpack(const double *x, ContactNodeState &n)
    {
      n.gap               = x[0];
      n.weight            = x[1];
      n.pressure          = x[2];
      n.tangential        = {{x[3], x[4]}};
      n.slip_rate         = {{x[5], x[6]}};
      n.projected         = x[7] > 0.5;
      n.active            = x[8] > 0.5;
      n.stick             = x[9] > 0.5;
      n.persistent        = x[10] > 0.5;
      n.gap_rate          = x[11];
      n.gap_acceleration  = x[12];
      n.velocity_rate     = x[13];
      n.held_gap          = x[14];
      n.held_rate         = x[15];
      n.held_acceleration = x[16];
    }

    std::string
    pair_key(const unsigned int p)
    {
      return "contact/pair " + std::to_string(p) + "/";
    }
  } // namespace

  template <int dim>
  std::vector<VectorType *>
  SurfaceContact<dim>::history_vectors()
  {
    std::vector<VectorType *> vectors = work.committed_forces();
    vectors.push_back(&gap_field);
    for (auto &field : slip_field)
      vectors.push_back(&field);
    return vectors;
  }

  template <int dim>
  void
  SurfaceContact<dim>::save_per_process(
    CheckpointData                               &data,
    const std::string                            &name,
    const std::vector<std::vector<unsigned int>> &lists) const
  {
    std::vector<double> flat{double(lists.size())};
    for (const auto &list : lists)
      {
        flat.push_back(list.size());
        flat.insert(flat.end(), list.begin(), list.end());
      }
    const auto all = Utilities::MPI::gather(comm, flat, 0);
    for (unsigned int r = 0; r < all.size(); ++r)
      data.set(name + "/process " + std::to_string(r), all[r]);
  }

  template <int dim>
  std::vector<std::vector<unsigned int>>
  SurfaceContact<dim>::load_per_process(const CheckpointData &data,
                                        const std::string    &name) const
  {
    std::vector<std::vector<unsigned int>> lists;
    if (data.value("processes") != Utilities::MPI::n_mpi_processes(comm))
      return lists;
    const auto &flat = data.get(name + "/process " +
                                std::to_string(
                                  Utilities::MPI::this_mpi_process(comm)));
    std::size_t i = 1;
    lists.resize(flat.at(0));
    for (auto &list : lists)
      {
        const std::size_t size = flat.at(i++);
        AssertThrow(i + size <= flat.size(),
                    ExcMessage("A checkpoint entry '" + name +
                               "' is damaged."));
        list.assign(flat.begin() + i, flat.begin() + i + size);
        i += size;
      }
    return lists;
  }

  template <int dim>
  void
  SurfaceContact<dim>::save_history(CheckpointData &data) const
  {
    data.set("contact/pairs", pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const PairData     &pair = pairs[p];
        const std::string   key  = pair_key(p);
        const unsigned int  n    = pair.nodes.size();
        std::vector<double> states(n_saved_fields * n, 0.), reference;
        // each node from the process that owns it (zeros elsewhere)
        for (unsigned int j = 0; j < n; ++j)
          if (pair.owned_node[j])
            pack(pair.nodes[j], &states[n_saved_fields * j]);
        Utilities::MPI::sum(states, comm, states);
        for (const auto &x : pair.secondary.reference)
          reference.insert(reference.end(), x.begin_raw(), x.end_raw());
        data.set(key + "nodes", states);
        data.set(key + "reference", reference);
        std::vector<double> reaction;
        const auto         &r = pair.committed_reaction;
        for (const auto *t : {&r.force, &r.friction_force})
          reaction.insert(reaction.end(), t->begin_raw(), t->end_raw());
        for (const auto *t : {&r.torque, &r.friction_torque})
          reaction.insert(reaction.end(), t->begin_raw(), t->end_raw());
        data.set(key + "reaction", reaction);
        // (3-D obstacles: chosen at the placement of the setup's time)
        data.set(key + "tangent axis",
                 std::vector<double>(pair.tangent_axis.begin(),
                                     pair.tangent_axis.end()));
        save_per_process(data, key + "pattern", pair.pattern);
      }
    data.set("contact/obstacle work",
             {obstacle_work_done,
              obstacle_friction_work,
              obstacle_normal_step_work});
    data.set("contact/work", {work.work(), work.dissipation()});
  }

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
        const auto  &saved = data.get(pair_key(p) + "reference");
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
            std::array<double, dim> x;
            std::copy(nodes[j].begin_raw(), nodes[j].end_raw(), x.begin());
            AssertThrow(index.emplace(x, j).second,
                        ExcMessage("The contact pair '" +
                                   contact.pairs[p].name +
                                   "' has two secondary nodes at " +
                                   coordinates(nodes[j]) +
                                   ": a checkpoint of another number of "
                                   "processes cannot tell them apart."));
          }
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            std::array<double, dim> x;
            Point<dim>              where;
            for (unsigned int d = 0; d < dim; ++d)
              where[d] = x[d] = saved[dim * k + d];
            const auto it = index.find(x);
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

  template <int dim>
  void
  SurfaceContact<dim>::load_history(const CheckpointData &data,
                                    const VectorType     &u)
  {
    const auto maps = saved_node_map(data);
    committed_u     = u;
    // the next update_candidates() searches from this committed state
    committed_is_next = false;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        PairData          &pair = pairs[p];
        const std::string  key  = pair_key(p);
        const unsigned int n    = pair.nodes.size();
        const auto        &states = data.get(key + "nodes", n_saved_fields * n);
        for (unsigned int k = 0; k < n; ++k)
          {
            const unsigned int j = maps[p].empty() ? k : maps[p][k];
            unpack(&states[n_saved_fields * k], pair.nodes[j]);
          }
        for (unsigned int j = 0; j < n; ++j)
          pair.position[j] = pair.secondary.position(j, u);
        const auto &axes = data.get(key + "tangent axis");
        if (axes.size() == pair.tangent_axis.size())
          for (unsigned int k = 0; k < axes.size(); ++k)
            pair.tangent_axis[maps[p].empty() ? k : maps[p][k]] = axes[k];
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
        // the sparsity of the run that wrote it, if numbered as here
        auto pattern = maps[p].empty() ?
                         load_per_process(data, key + "pattern") :
                         std::vector<std::vector<unsigned int>>();
        if (pattern.size() == n_patches(pair))
          pair.pattern = std::move(pattern);
        else if (pair.obstacle)
          pair.pattern.assign(n_patches(pair), {0});
        else
          pair.pattern = compute_candidates(pair, u, 2.0);
      }
    const auto &obstacle = data.get("contact/obstacle work", 3);
    obstacle_work_done        = obstacle[0];
    obstacle_friction_work    = obstacle[1];
    obstacle_normal_step_work = obstacle[2];
    const auto &totals        = data.get("contact/work", 2);
    work.carry_totals(totals[0], totals[1]);
  }

  template class SurfaceContact<2>;
  template class SurfaceContact<3>;
} // namespace ContactDynamics

#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>

#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/node_to_segment_contact.h>
#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace ContactDynamics
{
  using ContactAD::constant;
  using ContactAD::value;
  using SegmentGeometry::Vec;

  void
  NodeToSegmentParameters::declare_parameters(ParameterHandler &prm)
  {
    const NodeToSegmentParameters defaults;
    ComplementarityParameters::declare_parameters(prm,
                                                  defaults.complementarity);
    prm.declare_entry(
      "Normal smoothing distance",
      default_text(defaults.smoothing_distance),
      Patterns::Double(0, 0.5),
      "Fraction of a primary face, at each of its ends, over which the normal "
      "blends linearly into the average with the neighbouring face's normal "
      "(continuous at the node), in [0, 0.5]: 0 = no smoothing, 0.5 = "
      "maximal smoothing (the paper's 'NTS with normal smoothing').");
  }

  void
  NodeToSegmentParameters::parse_parameters(ParameterHandler &prm)
  {
    complementarity.parse_parameters(prm);
    smoothing_distance = prm.get_double("Normal smoothing distance");
  }



  template <int dim>
  NodeToSegmentContact<dim>::NodeToSegmentContact(
    const ContactParameters       &contact,
    const NodeToSegmentParameters &parameters)
    : SurfaceContact<dim>(contact, parameters.complementarity)
    , smoothing_distance(parameters.smoothing_distance)
    , face_memory(this->comm,
                  [this]() {
                    return this->n_pairs();
                  })
    , trial_face(face_memory.trial)
  {
    this->history.add(face_memory);
  }

  template <int dim>
  std::set<unsigned int>
  NodeToSegmentContact<dim>::primary_nodes(
    const PairData                  &pair,
    const std::vector<unsigned int> &faces) const
  {
    // the nodes of the primary faces and, for the smoothed normals near
    // the face ends, of their neighbours: in 2-D the adjacent faces' other
    // nodes, in 3-D the faces around every node (its nodal normal)
    const auto            &p = pair.primary;
    std::set<unsigned int> nodes;
    if (p.degree == 2)
      {
        // (2-D) every node of the curves and, smoothed, of their neighbours
        for (const unsigned int f : faces)
          for (const unsigned int node : p.faces[f])
            for (const unsigned int g : p.node_faces[node])
              if (g == f || smoothing_distance > 0)
                nodes.insert(p.face_nodes[g].begin(), p.face_nodes[g].end());
        return nodes;
      }
    for (const unsigned int f : faces)
      for (const unsigned int node : p.faces[f])
        {
          nodes.insert(node);
          if constexpr (dim == 2)
            {
              const unsigned int other = p.neighbour(node, f);
              if (other != ContactSurface<dim>::invalid)
                nodes.insert(other);
            }
          else if (smoothing_distance > 0)
            for (const unsigned int g : p.node_faces[node])
              nodes.insert(p.faces[g].begin(), p.faces[g].end());
        }
    return nodes;
  }

  template <int dim>
  double
  NodeToSegmentContact<dim>::traction_per_multiplier(const PairData    &pair,
                                                     const unsigned int node,
                                                     const VectorType  &u) const
  {
    // 2-D: the change of the length around the node (3-D:
    // node_to_segment_contact_3d.cc)
    const auto &surface = pair.secondary;
    if (surface.degree == 2)
      return surface.reference_weight[node] / surface.current_weight(node, u);
    double current = 0;
    for (const unsigned int face : surface.node_faces[node])
      {
        double length;
        surface.face_box(face, u, length);
        current += length / 2;
      }
    return current > 0 ? surface.reference_weight[node] / current : 1.;
  }

  template <int dim>
  BoundingBox<dim>
  NodeToSegmentContact<dim>::patch_box(const PairData    &pair,
                                       const unsigned int node,
                                       const VectorType  &u,
                                       double            &size) const
  {
    const Point<dim> x = pair.secondary.position(node, u);
    // (a length: the weight is an area in 3-D)
    const double weight = pair.secondary.reference_weight[node];
    size                = 2 * (dim == 2 ? weight : std::sqrt(weight));
    return BoundingBox<dim>(std::make_pair(x, x));
  }

  template <int dim>
  std::vector<types::global_dof_index>
  NodeToSegmentContact<dim>::patch_unknowns(
    const PairData                  &pair,
    const unsigned int               node,
    const std::vector<unsigned int> &primary_faces) const
  {
    std::vector<types::global_dof_index> unknowns;
    for (unsigned int d = 0; d < dim; ++d)
      unknowns.push_back(pair.secondary.dofs[node][d]);
    for (const unsigned int n : primary_nodes(pair, primary_faces))
      for (unsigned int d = 0; d < dim; ++d)
        unknowns.push_back(pair.primary.dofs[n][d]);
    // the normal and the dim - 1 tangential multipliers
    for (unsigned int c = 0; c < dim; ++c)
      unknowns.push_back(pair.secondary.dofs[node][dim + c]);
    return unknowns;
  }

  namespace
  {
    // the primary face closest to secondary node j at x and the parameter
    // of the projection on it; `previous`: the face of node j's projection
    // in the previous iteration of this attempt
    template <int dim, typename PairData, typename AD>
    unsigned int
    closest_face(const PairData                        &pair,
                 const unsigned int                     j,
                 const Vec<double>                     &x,
                 const std::map<unsigned int, Vec<AD>> &xp,
                 const VectorType                      &u,
                 const unsigned int                     previous,
                 double                                &best_eta)
    {
      const auto &s = pair.secondary;
      const auto &p = pair.primary;
      // the secondary node's own normal, to skip faces seen from behind
      Vec<double> n_s;
      for (const unsigned int f : s.node_faces[j])
        {
          Vec<double> a, b;
          for (unsigned int k = 0; k < 2; ++k)
            {
              a[k] = s.position(s.faces[f][0], u)[k];
              b[k] = s.position(s.faces[f][1], u)[k];
            }
          n_s += SegmentGeometry::face_normal(a, b);
        }

      // A node keeps the face it projected onto in the previous iteration
      // while it stays within a small tolerance of that face: at a concave
      // kink of the primary surface two faces are equally close, and
      // switching between them at every Newton iteration (their normals
      // differ) would stall the iteration. The memory starts from the
      // committed one at every attempt, so that nothing of a failed attempt
      // carries over.
      constexpr double tangential_tolerance = 1e-2;
      unsigned int     best                 = ContactSurface<dim>::invalid;
      double           best_distance        = 1e300;
      best_eta                              = 0;
      for (const unsigned int f : pair.candidates[j])
        {
          const Vec<double> y0 = value(xp.at(p.faces[f][0]));
          const Vec<double> y1 = value(xp.at(p.faces[f][1]));
          const Vec<double> t  = (y1 - y0) / 2.;
          const Vec<double> m  = (y0 + y1) / 2.;
          if (SegmentGeometry::face_normal(y0, y1) * n_s >= 0)
            continue;
          const double eta_free = (x - m) * t / (t * t);
          if (f == previous && std::abs(eta_free) <= 1 + tangential_tolerance)
            {
              best     = f;
              best_eta = eta_free;
              break;
            }
          const double eta      = std::max(-1., std::min(1., eta_free));
          const double distance = (x - (m + eta * t)).norm();
          if (distance < best_distance)
            {
              best          = f;
              best_distance = distance;
              // within the tolerance the projection extends the face, as it
              // does for a kept face
              best_eta =
                std::abs(eta_free) <= 1 + tangential_tolerance ? eta_free : eta;
            }
        }
      return best;
    }

    // the primary normal at eta on the face, blended within
    // `smoothing_distance` of its ends into the neighbours' normals
    template <int dim, typename PairData, typename AD>
    Vec<AD>
    smoothed_normal(const PairData                        &pair,
                    const unsigned int                     face,
                    const AD                              &eta,
                    const std::map<unsigned int, Vec<AD>> &xp,
                    const double                           smoothing_distance)
    {
      const auto    &p  = pair.primary;
      const Vec<AD> &y0 = xp.at(p.faces[face][0]),
                    &y1 = xp.at(p.faces[face][1]);
      Vec<AD> normal    = SegmentGeometry::face_normal(y0, y1);
      if (smoothing_distance <= 0)
        return normal;
      // within the smoothing distance of a face end the normal blends
      // linearly into the mean of the two faces' normals at that node
      const Vec<AD> face_normal = normal;
      for (const unsigned int end : {0u, 1u})
        {
          const AD to_end =
            end == 0 ? AD((1. + eta) / 2.) : AD((1. - eta) / 2.);
          const unsigned int node  = p.faces[face][end];
          const unsigned int other = p.neighbour(node, face);
          if (to_end.val() >= smoothing_distance ||
              other == ContactSurface<dim>::invalid)
            continue;
          // the neighbour face, oriented like the surface
          const Vec<AD> n_other =
            end == 0 ? SegmentGeometry::face_normal(xp.at(other), y0) :
                       SegmentGeometry::face_normal(y1, xp.at(other));
          // (1 beyond the end, where the face memory extends the face)
          const AD weight =
            to_end.val() <= 0 ?
              AD(1.) :
              AD((smoothing_distance - to_end) / smoothing_distance);
          normal += AD(weight / 2.) * (n_other - face_normal);
        }
      normal /= SegmentGeometry::norm(normal);
      return normal;
    }
  } // namespace

  template <int dim>
  void
  NodeToSegmentContact<dim>::assemble_patch(PairData          &pair,
                                            const unsigned int j,
                                            const TrialState  &state,
                                            PatchForces       &forces)
  {
    const auto unknowns = patch_unknowns(pair, j, pair.candidates[j]);
    ContactAD::dispatch(unknowns.size(), [&](const auto zero) {
      using AD = std::decay_t<decltype(zero)>;
      if (pair.primary.degree == 2)
        assemble_quadratic_patch_ad<AD>(pair, j, state, unknowns, forces);
      else
        assemble_patch_ad<AD>(pair, j, state, unknowns, forces);
    });
  }



  template <int dim>
  template <typename AD>
  void
  NodeToSegmentContact<dim>::assemble_patch_ad(
    PairData                                   &pair,
    const unsigned int                          j,
    const TrialState                           &state,
    const std::vector<types::global_dof_index> &unknowns,
    PatchForces                                &forces)
  {
    const auto &s     = pair.secondary;
    const auto &p     = pair.primary;
    const auto &faces = pair.candidates[j];
    const bool  exact = this->complementarity.exact_jacobian;

    ContactAD::NodeVariables<dim, AD> variables(unknowns, state);
    Vec<AD>                           x, v;
    std::map<unsigned int, Vec<AD>>   xp, vp;
    variables.add(s, j, x, v);
    for (const unsigned int node : primary_nodes(pair, faces))
      variables.add(p, node, xp[node], vp[node]);
    const AD lambda   = variables.multiplier();
    const AD lambda_t = variables.multiplier();

    // closest point projection
    auto &current = face_memory.trial_faces(pair.index);
    current.resize(s.n_nodes(), ContactSurface<dim>::invalid);
    double             best_eta = 0;
    const unsigned int best =
      closest_face<dim>(pair, j, value(x), xp, state.u, current[j], best_eta);
    current[j] = best;
    if (best == ContactSurface<dim>::invalid)
      return; // no projection: the node is inactive

    const unsigned int c = p.faces[best][0], d = p.faces[best][1];
    const Vec<AD>     &y0 = xp.at(c), &y1 = xp.at(d);
    const Vec<AD>      t   = (y1 - y0) / 2.;
    const Vec<AD>      m   = (y0 + y1) / 2.;
    AD                 eta = (x - m) * t / (t * t);
    if (std::abs(eta.val() - best_eta) > 1e-12 || !exact)
      eta = AD(best_eta); // clamped at a face end, or approximate
    Vec<AD> normal =
      smoothed_normal<dim>(pair, best, eta, xp, smoothing_distance);
    if (!exact)
      normal = constant(normal);

    const auto    N   = SegmentGeometry::shape(eta);
    const Vec<AD> x_p = N[0] * y0 + N[1] * y1;
    const AD      g   = (x - x_p) * normal;
    ContactAD::add_to(pair.gap[j], g, unknowns);
    pair.weight[j].value += 1.;
    // the secondary side's normal and tangent at the node, from the primary
    const Vec<AD> n_secondary = -normal;
    const Vec<AD> tangent     = SegmentGeometry::rotate(n_secondary);
    const bool    friction    = pair.friction_coefficient > 0;
    if ((this->complementarity.holds_contact() && state.dynamic) || friction)
      {
        const Vec<AD> v_rel = v - (N[0] * vp.at(c) + N[1] * vp.at(d));
        ContactAD::add_to(pair.gap_rate[j],
                          AD(-(v_rel * n_secondary)),
                          unknowns);
        if (friction)
          ContactAD::add_to(pair.slip_rate[j][0],
                            AD(v_rel * tangent),
                            unknowns);
      }

    // the nodal force L (lambda n + lambda_t t), with the secondary side's
    // normal n = -(primary normal) and tangent t, acts on the secondary node
    // and, with weights N(eta), opposite on the primary face
    const double  L   = s.reference_weight[j];
    const Vec<AD> f_t = AD(lambda_t * L) * tangent;
    const Vec<AD> f   = AD(lambda * L) * n_secondary + f_t;
    for (unsigned int k = 0; k < 2; ++k)
      {
        const AD rows[3] = {f[k], -N[0] * f[k], -N[1] * f[k]};
        const types::global_dof_index dofs[3] = {s.dofs[j][k],
                                                 p.dofs[c][k],
                                                 p.dofs[d][k]};
        for (unsigned int r = 0; r < 3; ++r)
          forces.add(dofs[r],
                     rows[r].val(),
                     ContactAD::derivatives(rows[r], unknowns));
        if (friction)
          {
            forces.add_tangential(s.dofs[j][k], f_t[k].val());
            forces.add_tangential(p.dofs[c][k], -N[0].val() * f_t[k].val());
            forces.add_tangential(p.dofs[d][k], -N[1].val() * f_t[k].val());
          }
      }
  }

  unsigned int
  FaceMemory::tangent_axis(const unsigned int           pair,
                           const unsigned int           j,
                           const unsigned int           n_nodes,
                           const std::array<double, 3> &normal)
  {
    auto &axes = trial_axis[pair];
    axes.resize(n_nodes, numbers::invalid_unsigned_int);
    unsigned int &axis = axes[j];
    // (a new axis starts at least 54.7 degrees from the normal;
    // tangent_basis() refuses one within about 17 degrees)
    if (axis < 3 && std::abs(normal[axis]) <= 0.8)
      return axis;
    axis = 0;
    for (unsigned int d = 1; d < 3; ++d)
      if (std::abs(normal[d]) < std::abs(normal[axis]))
        axis = d;
    return axis;
  }

  void
  FaceMemory::save(CheckpointData &data, const ContactHistoryContext &) const
  {
    for (const auto &[name, memory] :
         {std::make_pair("contact/faces", &committed),
          std::make_pair("contact/tangent axes", &committed_axis)})
      {
        std::vector<std::vector<unsigned int>> lists(n_pairs());
        for (const auto &[p, nodes] : *memory)
          lists[p] = nodes;
        save_per_process(comm, data, name, lists);
      }
  }

  void
  FaceMemory::load(const CheckpointData        &data,
                   const ContactHistoryContext &context)
  {
    committed.clear();
    committed_axis.clear();
    // on another numbering the faces are searched anew and the axes chosen
    // anew (checkpoints from before the axes were kept have none)
    if (!context.same_numbering())
      return;
    for (const auto &[name, memory] :
         {std::make_pair("contact/faces", &committed),
          std::make_pair("contact/tangent axes", &committed_axis)})
      if (data.has(std::string(name) + "/process 0"))
        {
          const auto lists = load_per_process(comm, data, name);
          for (unsigned int p = 0; p < lists.size(); ++p)
            if (!lists[p].empty())
              (*memory)[p] = lists[p];
        }
  }

  template class NodeToSegmentContact<2>;
  template class NodeToSegmentContact<3>;
} // namespace ContactDynamics

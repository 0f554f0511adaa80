// 3-D dual mortar patches: a secondary bilinear face with the unknowns it
// reads, its integrals (mortar_face_3d.cc, mortar_friction_3d.cc) added to
// the pair's nodes and to the forces. The forces follow the 2-D rule
// (mortar_contact.cc): -sum_j lambda_j w_j d(g_j / w_j)/du.
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/clipping_geometry.h>
#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/mortar_face_3d.h>

#include <algorithm>
#include <map>
#include <set>

namespace ContactDynamics
{
  namespace
  {
    // the nodes whose positions a face's integrals read
    template <typename PairData>
    std::set<unsigned int>
    ring_nodes(const PairData &pair, const unsigned int e)
    {
      std::set<unsigned int> nodes;
      for (const unsigned int node : pair.secondary.faces[e])
        for (const unsigned int f : pair.secondary.node_faces[node])
          nodes.insert(pair.secondary.faces[f].begin(),
                       pair.secondary.faces[f].end());
      return nodes;
    }

    template <typename PairData>
    std::set<unsigned int>
    primary_nodes(const PairData &pair, const std::vector<unsigned int> &faces)
    {
      std::set<unsigned int> nodes;
      for (const unsigned int f : faces)
        nodes.insert(pair.primary.faces[f].begin(),
                     pair.primary.faces[f].end());
      return nodes;
    }

    // The ring of secondary nodes around face e, then the primary nodes of
    // its candidates, in the order of patch_unknowns()
    template <typename PairData>
    MortarFace3D::PatchNodes
    position_nodes(const PairData &pair, const unsigned int e)
    {
      MortarFace3D::PatchNodes nodes;
      for (const unsigned int n : ring_nodes(pair, e))
        nodes.emplace_back(&pair.secondary, n);
      for (const unsigned int n : primary_nodes(pair, pair.candidates[e]))
        nodes.emplace_back(&pair.primary, n);
      return nodes;
    }

    // Adds the face's gaps, weights and rates to its nodes' values and
    // returns direction[i][j] = w_j d(g_j / w_j)/du_i
    template <typename PairData>
    std::vector<std::array<double, 4>>
    add_face_gaps(PairData                                   &pair,
                  const unsigned int                          e,
                  const MortarFace3D::FaceFirstOrder         &sums,
                  const std::vector<types::global_dof_index> &unknowns,
                  const unsigned int                          n_positions)
    {
      const auto &face = pair.secondary.faces[e];
      const auto  add  = [&](LinearizedValue                          &target,
                           const double                              value,
                           const std::vector<std::array<double, 4>> &d,
                           const unsigned int                        j) {
        target.value += value;
        for (unsigned int i = 0; i < n_positions; ++i)
          if (d[i][j] != 0)
            target.derivatives[unknowns[i]] += d[i][j];
      };
      std::vector<std::array<double, 4>> direction(n_positions,
                                                   {{0., 0., 0., 0.}});
      for (unsigned int j = 0; j < 4; ++j)
        {
          add(pair.gap[face[j]], sums.gap[j], sums.d_gap, j);
          add(pair.weight[face[j]], sums.weight[j], sums.d_weight, j);
          add(pair.gap_rate[face[j]], sums.gap_rate[j], sums.d_rate, j);
          if (sums.weight[j] > 0)
            {
              const double ratio = sums.gap[j] / sums.weight[j];
              for (unsigned int i = 0; i < n_positions; ++i)
                direction[i][j] =
                  sums.d_gap[i][j] - ratio * sums.d_weight[i][j];
            }
        }
      return direction;
    }

  } // namespace

  template <>
  void
  MortarContact<3>::add_friction(
    PairData                                   &pair,
    const std::vector<unsigned int>            &face,
    const MortarFace3D::FrictionTerms          &f,
    const std::vector<types::global_dof_index> &unknowns,
    const unsigned int                          n_positions,
    PatchForces                                &forces) const
  {
    for (unsigned int i = 0; i < n_positions; ++i)
      {
        typename PatchForces::Derivatives derivatives;
        for (unsigned int l = 0; l < f.d_force[i].size(); ++l)
          if (f.d_force[i][l] != 0)
            derivatives.emplace_back(unknowns[l], f.d_force[i][l]);
        if (f.force[i] != 0 || !derivatives.empty())
          {
            forces.add(unknowns[i], f.force[i], std::move(derivatives));
            forces.add_tangential(unknowns[i], f.force[i]);
          }
      }
    for (unsigned int j = 0; j < face.size(); ++j)
      for (unsigned int a = 0; a < 2; ++a)
        {
          LinearizedValue &slip = pair.slip_rate[face[j]][a];
          slip.value += f.slip[j][a];
          for (unsigned int i = 0; i < n_positions; ++i)
            if (f.d_slip[j][a][i] != 0)
              slip.derivatives[unknowns[i]] += f.d_slip[j][a][i];
        }
  }

  template <>
  std::vector<types::global_dof_index>
  MortarContact<3>::patch_unknowns(
    const PairData                  &pair,
    const unsigned int               e,
    const std::vector<unsigned int> &primary_faces) const
  {
    if (pair.secondary.degree == 2)
      return quadratic_patch_unknowns(pair, e, primary_faces);
    std::vector<types::global_dof_index> unknowns;
    for (const unsigned int n : ring_nodes(pair, e))
      for (unsigned int d = 0; d < 3; ++d)
        unknowns.push_back(pair.secondary.dofs[n][d]);
    for (const unsigned int n : primary_nodes(pair, primary_faces))
      for (unsigned int d = 0; d < 3; ++d)
        unknowns.push_back(pair.primary.dofs[n][d]);
    // the normal multipliers, then the tangential ones (with friction)
    for (const unsigned int n : pair.secondary.faces[e])
      unknowns.push_back(pair.secondary.dofs[n][3]);
    if (pair.friction_coefficient > 0)
      for (const unsigned int n : pair.secondary.faces[e])
        for (const unsigned int c : {4, 5})
          unknowns.push_back(pair.secondary.dofs[n][c]);
    return unknowns;
  }

  template <>
  void
  MortarContact<3>::assemble_patch(PairData          &pair,
                                   const unsigned int e,
                                   const TrialState  &state,
                                   PatchForces       &forces)
  {
    if (pair.secondary.degree == 2)
      return assemble_quadratic_patch(pair, e, state, forces);
    const bool exact    = this->complementarity.exact_jacobian;
    const auto unknowns = patch_unknowns(pair, e, pair.candidates[e]);
    const bool rates = this->complementarity.holds_contact() && state.dynamic;
    const bool friction = pair.friction_coefficient > 0;
    const ClippingGeometry::TriangleRule &rule =
      ClippingGeometry::triangle_rule(quadrature_points);

    const MortarFace3D::PatchNodes nodes       = position_nodes(pair, e);
    const unsigned int             n_positions = 3 * nodes.size();
    std::array<double, 4>          lambda;
    for (unsigned int j = 0; j < 4; ++j)
      lambda[j] = state.u(unknowns[n_positions + j]);

    std::vector<double> position(n_positions), velocity(n_positions);
    for (unsigned int i = 0; i < n_positions; ++i)
      {
        position[i] =
          nodes[i / 3].first->reference[nodes[i / 3].second][i % 3] +
          state.u(unknowns[i]);
        velocity[i] = state.v(unknowns[i]);
      }
    // the gaps, weights and rates of the face's nodes with their first
    // derivatives, and direction[i][j] = w_j d(g_j / w_j)/du_i
    const auto  sums     = MortarFace3D::first_order_sums(pair.secondary,
                                                     pair.primary,
                                                     pair.candidates[e],
                                                     e,
                                                     nodes,
                                                     position,
                                                     velocity,
                                                     state.c_v,
                                                     rates,
                                                     friction,
                                                     minimum_covered_fraction,
                                                     rule);
    const auto &covering = sums.covering;
    if (covering.empty())
      return;
    std::vector<std::array<double, 4>> direction =
      add_face_gaps(pair, e, sums, unknowns, n_positions);

    // 'approximate': the geometric stiffness (the derivatives of the
    // directions) is dropped
    std::vector<double> hessian(exact ? n_positions * n_positions : 0);
    // (weighted with the multipliers: nothing to compute without them, as
    // on faces out of contact; the second derivatives cost about as much
    // as a first-order pass per seeded position)
    if (exact && std::any_of(lambda.begin(), lambda.end(), [](double l) {
          return l != 0;
        }))
      {
        MortarFace3D::exact_directions(pair.secondary,
                                       pair.primary,
                                       e,
                                       nodes,
                                       covering,
                                       position,
                                       rule,
                                       lambda,
                                       direction,
                                       hessian);
      }
    forces.add_normal_rows(unknowns,
                           lambda,
                           direction,
                           hessian,
                           [](unsigned int, auto &) {});
    if (!friction)
      return;

    std::array<std::array<double, 2>, 4> lambda_t;
    for (unsigned int j = 0; j < 4; ++j)
      for (unsigned int a = 0; a < 2; ++a)
        lambda_t[j][a] = state.u(unknowns[n_positions + 4 + 2 * j + a]);
    const MortarFace3D::FrictionTerms f =
      MortarFace3D::friction_terms(pair.secondary,
                                   e,
                                   sums,
                                   velocity,
                                   state.c_v,
                                   lambda_t);
    const auto &face = pair.secondary.faces[e];
    add_friction(pair,
                 std::vector<unsigned int>(face.begin(), face.end()),
                 f,
                 unknowns,
                 n_positions,
                 forces);
  }
} // namespace ContactDynamics

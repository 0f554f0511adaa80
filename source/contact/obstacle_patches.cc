// The contact patches of a pair whose primary side is a rigid obstacle
// (rigid_obstacle.h), for both formulations in 2-D and 3-D: the gap is the
// signed distance to the analytic surface, the normal its gradient, and
// the primary side has no unknowns. Node-to-segment enforces the distance
// at the secondary nodes; the dual mortar formulation its integrals with
// the dual basis over the whole secondary face (the obstacle covers every
// face), with the variationally consistent normal force of the meshed
// pairs. Both differentiate everything exactly (automatic differentiation).
#include <deal.II/base/quadrature_lib.h>

#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/node_to_segment_contact.h>
#include <contact_dynamics/contact/quadratic_face.h>
#include <contact_dynamics/contact/surface_geometry_3d.h>

#include <array>

namespace ContactDynamics
{
  namespace
  {
    template <int dim, typename Number>
    using Vector = Tensor<1, dim, Number>;

    template <int dim>
    constexpr unsigned int nodes_per_face =
      GeometryInfo<dim>::vertices_per_face;

    /** The dim - 1 tangents of a node with the secondary normal n. */
    template <int dim, typename Number>
    std::array<Vector<dim, Number>, dim - 1>
    node_tangents(const Vector<dim, Number> &n, const unsigned int axis)
    {
      if constexpr (dim == 2)
        return {{SegmentGeometry::rotate(n)}};
      else
        {
          // the surface's axis (obstacle_coupling.cc); at a node far from
          // the contact (no tangential force there) the obstacle's normal
          // may lie nearly along it (a small sphere, a cylinder rolling
          // along x): there the axis least aligned with that normal
          using std::abs;
          unsigned int a = axis;
          if (abs(MortarGeometry::value_of(n[a])) > 0.9)
            for (unsigned int d = 0; d < 3; ++d)
              if (abs(MortarGeometry::value_of(n[d])) <
                  abs(MortarGeometry::value_of(n[a])))
                a = d;
          return ClippingGeometry::tangent_basis(n, a);
        }
    }

    /**
     * Shape functions of a face with n nodes on [0,1]^(dim-1): the vertices
     * lexicographic, then (degree 2) as in QuadraticFace.
     */
    template <int dim, unsigned int n, typename Number>
    std::array<Number, n>
    face_shape(const Point<dim - 1> &q)
    {
      if constexpr (n != nodes_per_face<dim>)
        {
          const auto            N = QuadraticFace::shape<dim>(q).N;
          std::array<Number, n> result;
          for (unsigned int j = 0; j < n; ++j)
            result[j] = Number(N[j]);
          return result;
        }
      else if constexpr (dim == 2)
        return {{Number(1. - q[0]), Number(q[0])}};
      else
        return ClippingGeometry::shape(Number(q[0]), Number(q[1]));
    }

    /** The area (length) element of a face at q. */
    template <int dim, unsigned int n, typename Number>
    Number
    area_element(const std::array<Vector<dim, Number>, n> &x,
                 const Point<dim - 1>                     &q)
    {
      using std::sqrt;
      if constexpr (n != nodes_per_face<dim>)
        return QuadraticFace::area_element<dim>(QuadraticFace::shape<dim>(q).dN,
                                                x);
      else if constexpr (dim == 2)
        {
          const Vector<2, Number> t = x[1] - x[0];
          return sqrt(t * t);
        }
      else
        {
          const auto t =
            ClippingGeometry::tangents(x, Number(q[0]), Number(q[1]));
          return ClippingGeometry::norm(ClippingGeometry::cross(t[0], t[1]));
        }
    }

    /** The integrals of one secondary face against an obstacle. */
    template <int dim, unsigned int n, typename Number>
    struct FaceSums
    {
      std::array<Number, n>                      gap, weight, gap_rate;
      std::array<std::array<Number, dim - 1>, n> slip_rate;
      std::array<Vector<dim, Number>, n>         friction_force;
    };

    /**
     * The weighted gaps g_j = int psi_j phi and weights w_j = int N_j of a
     * face with nodes x (dual basis psi of the whole face); with velocities
     * v, the rates int psi_j (v - v_obstacle).grad phi; with the nodal
     * tangents t and tangential multipliers lambda_t, the slip rates
     * int psi_j (v - v_obstacle).t_j and the friction forces
     * int N_i sum_j psi_j lambda_t,j t_j.
     */
    template <int dim, unsigned int n, typename Number>
    FaceSums<dim, n, Number>
    face_sums(const RigidObstacle<dim>                     &obstacle,
              const typename RigidObstacle<dim>::Placement &place,
              const std::array<Vector<dim, Number>, n>     &x,
              const std::array<Vector<dim, Number>, n>     *v,
              const std::array<std::array<Vector<dim, Number>, dim - 1>, n> *t,
              const std::array<std::array<Number, dim - 1>, n> *lambda_t,
              const QGauss<dim - 1>                            &quadrature)
    {
      FaceSums<dim, n, Number> sums;
      for (unsigned int j = 0; j < n; ++j)
        {
          sums.gap[j] = sums.weight[j] = sums.gap_rate[j] = Number(0.);
          for (auto &s : sums.slip_rate[j])
            s = Number(0.);
        }
      // the dual basis of the face: A = D M^-1 on its quadrature
      std::vector<Number>                  JxW(quadrature.size());
      std::array<Number, n>                D;
      std::array<std::array<Number, n>, n> M;
      D.fill(Number(0.));
      for (auto &row : M)
        row.fill(Number(0.));
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          JxW[q] =
            quadrature.weight(q) * area_element<dim, n>(x, quadrature.point(q));
          const auto N = face_shape<dim, n, Number>(quadrature.point(q));
          for (unsigned int j = 0; j < n; ++j)
            {
              D[j] += N[j] * JxW[q];
              for (unsigned int k = 0; k < n; ++k)
                M[j][k] += N[j] * N[k] * JxW[q];
            }
        }
      std::array<std::array<Number, n>, n> A;
      if constexpr (n == 2)
        {
          const Number det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
          A                = {{{{D[0] * M[1][1] / det, -D[0] * M[0][1] / det}},
                               {{-D[1] * M[1][0] / det, D[1] * M[0][0] / det}}}};
        }
      else
        A = ClippingGeometry::dual_from_moments(D, M);

      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const auto N = face_shape<dim, n, Number>(quadrature.point(q));
          std::array<Number, n> psi;
          Vector<dim, Number>   xq;
          for (unsigned int j = 0; j < n; ++j)
            {
              psi[j] = Number(0.);
              for (unsigned int k = 0; k < n; ++k)
                psi[j] += A[j][k] * N[k];
              xq += N[j] * x[j];
            }
          Vector<dim, Number> normal;
          const Number        phi = obstacle.signed_distance(place, xq, normal);
          for (unsigned int j = 0; j < n; ++j)
            {
              sums.gap[j] += psi[j] * phi * JxW[q];
              sums.weight[j] += N[j] * JxW[q];
            }
          if (v != nullptr)
            {
              Vector<dim, Number> vq;
              for (unsigned int j = 0; j < n; ++j)
                vq += N[j] * (*v)[j];
              // the obstacle's point that touches xq
              const Vector<dim, Number> y = xq - phi * normal;
              const Vector<dim, Number> v_rel =
                vq - obstacle.velocity(place, y);
              for (unsigned int j = 0; j < n; ++j)
                {
                  sums.gap_rate[j] += psi[j] * (v_rel * normal) * JxW[q];
                  if (t != nullptr)
                    for (unsigned int k = 0; k < dim - 1; ++k)
                      sums.slip_rate[j][k] +=
                        psi[j] * (v_rel * (*t)[j][k]) * JxW[q];
                }
            }
          if (lambda_t != nullptr)
            {
              Vector<dim, Number> z_t;
              for (unsigned int j = 0; j < n; ++j)
                for (unsigned int k = 0; k < dim - 1; ++k)
                  z_t += Number(psi[j] * (*lambda_t)[j][k]) * (*t)[j][k];
              for (unsigned int i = 0; i < n; ++i)
                sums.friction_force[i] += Number(N[i] * JxW[q]) * z_t;
            }
        }
      return sums;
    }

    /**
     * Whether a face outside the obstacle turns its outward normal away
     * from it (the back of a body).
     */
    template <int dim, typename PairData, std::size_t n>
    bool
    faces_away(const PairData &pair, const std::array<Point<dim>, n> &x)
    {
      Tensor<1, dim> outward;
      Point<dim>     center;
      for (const auto &p : x)
        center += p / double(x.size());
      if constexpr (dim == 2)
        {
          outward[0] = x[1][1] - x[0][1];
          outward[1] = x[0][0] - x[1][0];
        }
      else
        outward = cross_product_3d(x[1] - x[0], x[2] - x[0]);
      // (a face behind the surface still counts: a body that went inside
      // is pushed out)
      Tensor<1, dim> normal;
      const double   phi = pair.obstacle->signed_distance(pair.trial_place,
                                                        Tensor<1, dim>(center),
                                                        normal);
      return outward * normal >= 0 && phi > 0;
    }

    // The directions w_j d(g_j / w_j)/du_i of the normal force of face
    // `face` of `s` against the obstacle at `place`, with their
    // derivatives weighted with the multipliers, hessian[i n + l] = sum_j
    // lambda_j d direction[i][j]/du_l: second derivatives in the positions
    template <int dim, unsigned int n, typename Face>
    void
    obstacle_directions(const RigidObstacle<dim>                     &obstacle,
                        const typename RigidObstacle<dim>::Placement &place,
                        const ContactSurface<dim>                    &s,
                        const Face                                   &face,
                        const TrialState                             &state,
                        const std::vector<types::global_dof_index>   &unknowns,
                        const QGauss<dim - 1>              &quadrature,
                        const std::array<double, n>        &lambda,
                        std::vector<std::array<double, n>> &direction,
                        std::vector<double>                &hessian)
    {
      constexpr unsigned int n_positions = n * dim;
      const auto             compute     = [&](const auto zero) {
        using AD2   = std::decay_t<decltype(zero)>;
        using Inner = typename AD2::value_type;
        std::array<Vector<dim, AD2>, n> x;
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int d = 0; d < dim; ++d)
            {
              const unsigned int i = a * dim + d;
              const double       value =
                s.reference[face[a]][d] + state.u(unknowns[i]);
              x[a][d] = AD2(n_positions, i, Inner(n_positions, i, value));
            }
        const auto sums = face_sums<dim, n, AD2>(obstacle,
                                                 place,
                                                 x,
                                                 nullptr,
                                                 nullptr,
                                                 nullptr,
                                                 quadrature);
        for (unsigned int i = 0; i < n_positions; ++i)
          {
            std::array<Inner, n> d;
            for (unsigned int j = 0; j < n; ++j)
              {
                const AD2 ratio = sums.gap[j] / sums.weight[j];
                d[j]            = sums.weight[j].val() *
                       (ratio.size() > int(i) ? ratio.dx(i) : Inner(0.));
                direction[i][j] = d[j].val();
              }
            for (unsigned int l = 0; l < n_positions; ++l)
              {
                double h = 0;
                for (unsigned int j = 0; j < n; ++j)
                  if (d[j].size() > int(l))
                    h += lambda[j] * d[j].dx(l);
                hessian[i * n_positions + l] = h;
              }
          }
      };
      // faces of degree 2: second derivatives of fixed length (6 or 27
      // positions: 2.5 times faster than the nested dynamic type on the
      // rigid sphere)
      if constexpr (n != nodes_per_face<dim>)
        compute(ContactAD::FixedAD2<n_positions>(0.));
      else
        ContactAD::dispatch_second(n_positions, compute);
    }
  } // namespace



  template <int dim>
  void
  NodeToSegmentContact<dim>::assemble_obstacle_patch(PairData          &pair,
                                                     const unsigned int j,
                                                     const TrialState  &state,
                                                     PatchForces       &forces)
  {
    const auto unknowns = this->obstacle_patch_unknowns(pair, j);
    ContactAD::dispatch(unknowns.size(), [&](const auto zero) {
      using AD                            = std::decay_t<decltype(zero)>;
      const auto                       &s = pair.secondary;
      ContactAD::NodeVariables<dim, AD> variables(unknowns, state);
      Vector<dim, AD>                   x, v;
      variables.add(s, j, x, v);
      const AD                lambda = variables.multiplier();
      std::array<AD, dim - 1> lambda_t;
      for (auto &l : lambda_t)
        l = variables.multiplier();

      Vector<dim, AD> normal;
      const AD g = pair.obstacle->signed_distance(pair.trial_place, x, normal);
      ContactAD::add_to(pair.gap[j], g, unknowns);
      pair.weight[j].value += 1.;
      const Vector<dim, AD> n_secondary = -normal;
      const bool            friction    = pair.friction_coefficient > 0;
      // (tangents only with friction: they need not exist otherwise)
      std::array<Vector<dim, AD>, dim - 1> t;
      if (friction)
        t = node_tangents<dim>(n_secondary, pair.tangent_axis[j]);
      if ((this->complementarity.holds_contact() && state.dynamic) || friction)
        {
          const Vector<dim, AD> y = x - g * normal;
          const Vector<dim, AD> v_rel =
            v - pair.obstacle->velocity(pair.trial_place, y);
          ContactAD::add_to(pair.gap_rate[j],
                            AD(-(v_rel * n_secondary)),
                            unknowns);
          if (friction)
            for (unsigned int k = 0; k < dim - 1; ++k)
              ContactAD::add_to(pair.slip_rate[j][k],
                                AD(v_rel * t[k]),
                                unknowns);
        }
      // the nodal force L (lambda n + lambda_t t) on the secondary node
      const double    L = s.reference_weight[j];
      Vector<dim, AD> f_t;
      for (unsigned int k = 0; k < dim - 1; ++k)
        f_t += AD(lambda_t[k] * L) * t[k];
      const Vector<dim, AD> f = AD(lambda * L) * n_secondary + f_t;
      for (unsigned int d = 0; d < dim; ++d)
        {
          forces.add(s.dofs[j][d],
                     f[d].val(),
                     ContactAD::derivatives(f[d], unknowns));
          if (friction)
            forces.add_tangential(s.dofs[j][d], f_t[d].val());
        }
    });
  }



  namespace
  {
    /**
     * The mortar patch of face e of the pair's secondary surface, whose
     * faces have n nodes, against the obstacle: with the unknowns of
     * obstacle_patch_unknowns() and `rates` if the complementarity holds
     * gap rates.
     */
    template <int dim, unsigned int n, typename PairData>
    void
    assemble_obstacle_face(PairData                                   &pair,
                           const unsigned int                          e,
                           const TrialState                           &state,
                           const std::vector<types::global_dof_index> &unknowns,
                           const QGauss<dim - 1> &quadrature,
                           const bool             rates,
                           PatchForces           &forces)
    {
      constexpr unsigned int n_positions = n * dim;
      const auto            &s           = pair.secondary;
      const auto            &face        = s.face_nodes[e];
      {
        std::array<Point<dim>, n> x;
        for (unsigned int a = 0; a < n; ++a)
          x[a] = s.position(face[a], state.u);
        if (faces_away<dim>(pair, x))
          return;
      }
      const bool friction = pair.friction_coefficient > 0;
      // gaps, weights, rates and friction forces with first derivatives
      std::array<double, n> lambda;
      ContactAD::dispatch(unknowns.size(), [&](const auto zero) {
        using AD = std::decay_t<decltype(zero)>;
        ContactAD::NodeVariables<dim, AD> variables(unknowns, state);
        std::array<Vector<dim, AD>, n>    x, v;
        for (unsigned int a = 0; a < n; ++a)
          variables.add(s, face[a], x[a], v[a]);
        std::array<std::array<AD, dim - 1>, n> lambda_t;
        for (unsigned int a = 0; a < n; ++a)
          lambda[a] = variables.multiplier().val();
        for (unsigned int k = 0; k < dim - 1; ++k)
          for (unsigned int a = 0; a < n; ++a)
            lambda_t[a][k] = variables.multiplier();
        std::array<std::array<Vector<dim, AD>, dim - 1>, n> t;
        for (unsigned int a = 0; a < n && friction; ++a)
          {
            Vector<dim, AD> normal;
            pair.obstacle->signed_distance(pair.trial_place, x[a], normal);
            t[a] = node_tangents<dim>(Vector<dim, AD>(-normal),
                                      pair.tangent_axis[face[a]]);
          }
        const auto sums =
          face_sums<dim, n, AD>(*pair.obstacle,
                                pair.trial_place,
                                x,
                                rates || friction ? &v : nullptr,
                                friction ? &t : nullptr,
                                friction ? &lambda_t : nullptr,
                                quadrature);
        for (unsigned int a = 0; a < n; ++a)
          {
            const unsigned int j = face[a];
            ContactAD::add_to(pair.gap[j], sums.gap[a], unknowns);
            ContactAD::add_to(pair.weight[j], sums.weight[a], unknowns);
            // (+: the rate of phi is (v - v_o).grad phi = -(v - v_o).n_s)
            ContactAD::add_to(pair.gap_rate[j], sums.gap_rate[a], unknowns);
            for (unsigned int k = 0; k < dim - 1; ++k)
              ContactAD::add_to(pair.slip_rate[j][k],
                                sums.slip_rate[a][k],
                                unknowns);
            if (friction)
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const AD &f = sums.friction_force[a][d];
                  forces.add(s.dofs[j][d],
                             f.val(),
                             ContactAD::derivatives(f, unknowns));
                  forces.add_tangential(s.dofs[j][d], f.val());
                }
          }
      });

      // the normal force -sum_j lambda_j w_j d(g_j / w_j)/du (as for the
      // meshed pairs) with its derivatives: second derivatives in the
      // positions
      std::vector<std::array<double, n>> direction(n_positions);
      std::vector<double>                hessian(n_positions * n_positions);
      obstacle_directions<dim, n>(*pair.obstacle,
                                  pair.trial_place,
                                  s,
                                  face,
                                  state,
                                  unknowns,
                                  quadrature,
                                  lambda,
                                  direction,
                                  hessian);
      forces.add_normal_rows(unknowns,
                             lambda,
                             direction,
                             hessian,
                             [](const unsigned int,
                                typename PatchForces::Derivatives &) {});
    }
  } // namespace



  template <int dim>
  void
  MortarContact<dim>::assemble_obstacle_patch(PairData          &pair,
                                              const unsigned int e,
                                              const TrialState  &state,
                                              PatchForces       &forces)
  {
    const auto unknowns = this->obstacle_patch_unknowns(pair, e);
    const bool rates = this->complementarity.holds_contact() && state.dynamic;
    // the signed distance is curved: more points than the meshed pairs,
    // and one more for the products of quadratic shape functions
    if (pair.secondary.degree == 1)
      assemble_obstacle_face<dim, nodes_per_face<dim>>(pair,
                                                       e,
                                                       state,
                                                       unknowns,
                                                       QGauss<dim - 1>(
                                                         quadrature_points + 2),
                                                       rates,
                                                       forces);
    else
      assemble_obstacle_face<dim, QuadraticFace::n_nodes<dim>>(
        pair,
        e,
        state,
        unknowns,
        QGauss<dim - 1>(quadrature_points + 3),
        rates,
        forces);
  }

#define INSTANTIATE(Formulation, dim)                                         \
  template void Formulation<dim>::assemble_obstacle_patch(PairData &,         \
                                                          const unsigned int, \
                                                          const TrialState &, \
                                                          PatchForces &);
  INSTANTIATE(NodeToSegmentContact, 2)
  INSTANTIATE(NodeToSegmentContact, 3)
  INSTANTIATE(MortarContact, 2)
  INSTANTIATE(MortarContact, 3)
#undef INSTANTIATE
} // namespace ContactDynamics

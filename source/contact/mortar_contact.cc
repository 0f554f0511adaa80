#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/mortar_geometry.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <set>

namespace ContactDynamics
{
  using SegmentGeometry::Vec;

  template <int dim>
  MortarContact<dim>::MortarContact(const ContactParameters &contact,
                                    const MortarParameters  &mortar)
    : SurfaceContact<dim>(contact, mortar.complementarity)
    , quadrature_points(mortar.quadrature_points)
    , segment_edge_points(mortar.segment_edge_points)
  {
    // (one point per triangle leaves the mass matrix of the dual basis
    // singular: a triangular overlap has one point, the centroids of a
    // square's fan lie where (xi - 1/2)(eta - 1/2) vanishes)
    AssertThrow(dim == 2 || (quadrature_points >= 2 && quadrature_points <= 7),
                ExcMessage("Contact/Mortar/Segment quadrature points = " +
                           std::to_string(quadrature_points) +
                           ": in 3-D it selects a triangle rule with 2 to 7 "
                           "points per direction (6, 7, 15, 19, 28 or 37 "
                           "points); 1 point per triangle cannot define the "
                           "dual basis."));
  }

  namespace
  {
    template <int dim, typename PairData>
    std::set<unsigned int>
    primary_nodes(const PairData                  &pair,
                  const std::vector<unsigned int> &primary_faces)
    {
      std::set<unsigned int> nodes;
      for (const unsigned int pf : primary_faces)
        for (const unsigned int node : pair.primary.faces[pf])
          nodes.insert(node);
      return nodes;
    }
  } // namespace

  template <int dim>
  BoundingBox<dim>
  MortarContact<dim>::patch_box(const PairData    &pair,
                                const unsigned int patch,
                                const VectorType  &u,
                                double            &size) const
  {
    return pair.secondary.face_box(patch, u, size);
  }

  template <int dim>
  std::vector<types::global_dof_index>
  MortarContact<dim>::patch_unknowns(
    const PairData                  &pair,
    const unsigned int               face,
    const std::vector<unsigned int> &primary_faces) const
  {
    if (pair.secondary.degree == 2)
      return quadratic_patch_unknowns(pair, face, primary_faces);
    const auto                          &s = pair.secondary;
    const auto                          &f = s.faces[face];
    std::vector<types::global_dof_index> unknowns;
    for (const unsigned int n :
         {s.neighbour(f[0], face), f[0], f[1], s.neighbour(f[1], face)})
      if (n != ContactSurface<dim>::invalid)
        for (unsigned int d = 0; d < dim; ++d)
          unknowns.push_back(s.dofs[n][d]);
    for (const unsigned int n : primary_nodes<dim>(pair, primary_faces))
      for (unsigned int d = 0; d < dim; ++d)
        unknowns.push_back(pair.primary.dofs[n][d]);
    // normal and tangential multipliers
    for (const unsigned int c : {dim, dim + 1})
      for (const unsigned int n : f)
        unknowns.push_back(s.dofs[n][c]);
    return unknowns;
  }

  namespace
  {
    template <typename Number>
    double
    scalar(const Number &x)
    {
      return Sacado::ScalarValue<Number>::eval(x);
    }

    template <typename Number>
    Vec<double>
    scalar(const Vec<Number> &x)
    {
      return Vec<double>({scalar(x[0]), scalar(x[1])});
    }

    // the value only: drops derivatives (approximate Jacobians)
    template <typename Number>
    Vec<Number>
    frozen(const Vec<Number> &x)
    {
      return Vec<Number>({Number(scalar(x[0])), Number(scalar(x[1]))});
    }

    // a mortar patch: positions and velocities of the secondary nodes (the
    // face and its neighbours) and primary nodes, the face, its nodal
    // normals and tangents and its multipliers
    template <typename Number>
    struct MortarPatch
    {
      std::map<unsigned int, Vec<Number>> xs, vs, xp, vp;
      Vec<Number>                         x0, x1, n0, n1, t0, t1, face_n;
      Number                              half_length;
      Number                              lambda[2], lambda_t[2];
    };

    // the face geometry from the positions xs (nodal normals: average of
    // the adjacent unit face normals)
    template <typename Number, typename Surface>
    void
    set_face_geometry(const Surface       &s,
                      const unsigned int   e,
                      const bool           exact,
                      MortarPatch<Number> &m)
    {
      const auto face_normal = [&](const unsigned int f) {
        return SegmentGeometry::face_normal(m.xs.at(s.faces[f][0]),
                                            m.xs.at(s.faces[f][1]));
      };
      const auto nodal_normal = [&](const unsigned int node) {
        Vec<Number> sum;
        for (const unsigned int f : s.node_faces[node])
          sum += face_normal(f);
        sum /= SegmentGeometry::norm(sum);
        return exact ? sum : frozen(sum);
      };
      const auto &face = s.faces[e];
      m.x0             = m.xs.at(face[0]);
      m.x1             = m.xs.at(face[1]);
      m.n0             = nodal_normal(face[0]);
      m.n1             = nodal_normal(face[1]);
      m.face_n         = SegmentGeometry::face_normal(m.x0, m.x1);
      m.half_length    = SegmentGeometry::norm(Vec<Number>(m.x1 - m.x0)) / 2.;
      m.t0             = SegmentGeometry::rotate(m.n0);
      m.t1             = SegmentGeometry::rotate(m.n1);
    }

    // what the mortar segments of a patch add up
    template <typename Number>
    struct SegmentSums
    {
      // residual contributions of the tangential traction (the normal
      // ones derive from the weighted gaps) and, for approximate
      // Jacobians, of the normal traction along the nodal normals
      std::map<types::global_dof_index, Number> rows, normal_rows;
      std::map<types::global_dof_index, double> tangential_rows;
      Number gap[2], weight[2], gap_rate[2], slip_rate[2];
    };

    // the parameters lo < hi on the secondary face of the segment that the
    // primary face (y0, y1) covers, projected along the normal field;
    // false if it covers none
    template <typename Number>
    bool
    segment_bounds(const MortarPatch<Number> &m,
                   const Vec<Number>         &y0,
                   const Vec<Number>         &y1,
                   const bool                 exact,
                   Number                    &lo,
                   Number                    &hi)
    {
      double xi_c, xi_d;
      if (!MortarGeometry::project_along_normal_field(scalar(m.x0),
                                                      scalar(m.x1),
                                                      scalar(m.n0),
                                                      scalar(m.n1),
                                                      scalar(y0),
                                                      xi_c) ||
          !MortarGeometry::project_along_normal_field(scalar(m.x0),
                                                      scalar(m.x1),
                                                      scalar(m.n0),
                                                      scalar(m.n1),
                                                      scalar(y1),
                                                      xi_d))
        return false;
      const double lo_v = std::max(-1., std::min(xi_c, xi_d));
      const double hi_v = std::min(1., std::max(xi_c, xi_d));
      if (hi_v - lo_v < 1e-12)
        return false;
      // an end inside the face moves with the primary node it projects; a
      // primary node projecting onto the face's end (within the sliver
      // width dropped above) leaves it fixed, as the neighbouring face's
      // dropped sliver would have compensated its motion (otherwise a
      // secondary node on a primary vertex gets a one-sided tangential
      // force that Newton cannot remove)
      const auto end = [&](const double       bound,
                           const Vec<Number> &y,
                           const double       xi) -> Number {
        if (std::abs(bound - xi) > 0 || !exact ||
            std::abs(std::abs(xi) - 1) < 1e-12)
          return Number(bound);
        return MortarGeometry::project_along_normal_field(m.x0,
                                                          m.x1,
                                                          m.n0,
                                                          m.n1,
                                                          y,
                                                          xi);
      };
      lo = (lo_v == std::min(xi_c, xi_d)) ?
             end(lo_v, xi_c < xi_d ? y0 : y1, std::min(xi_c, xi_d)) :
             Number(lo_v);
      hi = (hi_v == std::max(xi_c, xi_d)) ?
             end(hi_v, xi_c < xi_d ? y1 : y0, std::max(xi_c, xi_d)) :
             Number(hi_v);
      return true;
    }

    // the gap at the point xi of the face along the interpolated normal to
    // the primary face (y0, y1), with the primary parameter eta
    template <typename Number>
    Number
    point_gap(const MortarPatch<Number> &m,
              const Number              &xi,
              const Vec<Number>         &y0,
              const Vec<Number>         &y1,
              const bool                 exact,
              Vec<Number>               &normal,
              Number                    &eta)
    {
      const auto        N = SegmentGeometry::shape(xi);
      const Vec<Number> x = N[0] * m.x0 + N[1] * m.x1;
      normal              = N[0] * m.n0 + N[1] * m.n1;
      normal /= SegmentGeometry::norm(normal);
      eta = MortarGeometry::intersect_line_with_face(x, normal, y0, y1);
      if (!exact)
        eta = Number(scalar(eta));
      const auto        Np = SegmentGeometry::shape(eta);
      const Vec<Number> y  = Np[0] * y0 + Np[1] * y1;
      return (y - x) * normal;
    }

    // the mortar segments of face e: the parts [lo, hi] that candidate
    // primary faces pf (facing it) cover; none if they cover a sliver only
    template <typename Number>
    struct Segments
    {
      std::vector<unsigned int>              faces;
      std::vector<std::pair<Number, Number>> bounds;
      // the dual basis of the covered part
      std::array<std::array<Number, 2>, 2> dual;
    };

    template <typename Number, typename PairData>
    Segments<Number>
    mortar_segments(const PairData            &pair,
                    const unsigned int         e,
                    const MortarPatch<Number> &m,
                    const bool                 exact,
                    const double               minimum_covered_fraction)
    {
      const auto      &p = pair.primary;
      Segments<Number> segments;
      double           covered = 0;
      for (const unsigned int pf : pair.candidates[e])
        {
          const Vec<Number> &y0 = m.xp.at(p.faces[pf][0]);
          const Vec<Number> &y1 = m.xp.at(p.faces[pf][1]);
          Number             lo, hi;
          // (in double: the test needs no derivatives)
          if (SegmentGeometry::face_normal(scalar(y0), scalar(y1)) *
                  scalar(m.face_n) >=
                0 ||
              !segment_bounds(m, y0, y1, exact, lo, hi))
            continue;
          segments.faces.push_back(pf);
          segments.bounds.emplace_back(lo, hi);
          covered += (scalar(hi) - scalar(lo)) / 2;
        }
      // the dual basis of the covered part (A_e = D_e M_e^-1 over all the
      // segments), linearized through the segment ends; a sliver (M_e
      // nearly singular) contributes nothing
      if (covered < minimum_covered_fraction)
        {
          segments.faces.clear();
          segments.bounds.clear();
        }
      if (!segments.bounds.empty())
        segments.dual = MortarGeometry::dual_coefficients(segments.bounds);
      return segments;
    }

    // the weighted gaps and weights of the face's two nodes
    template <typename Number>
    struct FaceIntegrals
    {
      std::array<Number, 2> gap{{Number(0.), Number(0.)}};
      std::array<Number, 2> weight{{Number(0.), Number(0.)}};
    };

    template <typename Number, typename PairData>
    FaceIntegrals<Number>
    weighted_gaps(const PairData            &pair,
                  const MortarPatch<Number> &m,
                  const Segments<Number>    &segments,
                  const QGauss<1>           &gauss)
    {
      const auto           &p = pair.primary;
      FaceIntegrals<Number> sums;
      for (unsigned int k = 0; k < segments.faces.size(); ++k)
        {
          const unsigned int pf = segments.faces[k];
          const Number      &lo = segments.bounds[k].first;
          const Number      &hi = segments.bounds[k].second;
          const Vec<Number> &y0 = m.xp.at(p.faces[pf][0]);
          const Vec<Number> &y1 = m.xp.at(p.faces[pf][1]);
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const Number xi  = lo + (hi - lo) * gauss.point(q)[0];
              const Number JxW = gauss.weight(q) * (hi - lo) * m.half_length;
              const auto   N   = SegmentGeometry::shape(xi);
              const auto   psi = MortarGeometry::dual_shape(xi, segments.dual);
              Vec<Number>  normal;
              Number       eta;
              const Number g = point_gap(m, xi, y0, y1, true, normal, eta);
              for (unsigned int i = 0; i < 2; ++i)
                {
                  sums.gap[i] += psi[i] * g * JxW;
                  sums.weight[i] += N[i] * JxW;
                }
            }
        }
      return sums;
    }

    // the gap, weight, rate and force integrals over the segment [lo, hi]
    // of face e that the primary face pf covers; `rates`: gap rates too
    template <typename Number, typename PairData>
    void
    integrate_segment(const PairData                             &pair,
                      const unsigned int                          e,
                      const unsigned int                          pf,
                      const MortarPatch<Number>                  &m,
                      const Number                               &lo,
                      const Number                               &hi,
                      const std::array<std::array<Number, 2>, 2> &dual,
                      const QGauss<1>                            &gauss,
                      const bool                                  rates,
                      const bool                                  exact,
                      SegmentSums<Number>                        &sums)
    {
      const auto        &s        = pair.secondary;
      const auto        &p        = pair.primary;
      const auto        &face     = s.faces[e];
      const bool         friction = pair.friction_coefficient > 0;
      const Vec<Number> &y0       = m.xp.at(p.faces[pf][0]);
      const Vec<Number> &y1       = m.xp.at(p.faces[pf][1]);
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const Number xi  = lo + (hi - lo) * gauss.point(q)[0];
          const Number JxW = gauss.weight(q) * (hi - lo) * m.half_length;
          const auto   N   = SegmentGeometry::shape(xi);
          const auto   psi = MortarGeometry::dual_shape(xi, dual);
          Vec<Number>  normal;
          Number       eta;
          const Number g  = point_gap(m, xi, y0, y1, exact, normal, eta);
          const auto   Np = SegmentGeometry::shape(eta);
          for (unsigned int i = 0; i < 2; ++i)
            {
              sums.gap[i] += psi[i] * g * JxW;
              sums.weight[i] += N[i] * JxW;
            }
          if (rates || friction)
            {
              const Vec<Number> v_s =
                N[0] * m.vs.at(face[0]) + N[1] * m.vs.at(face[1]);
              const Vec<Number> v_p = Np[0] * m.vp.at(p.faces[pf][0]) +
                                      Np[1] * m.vp.at(p.faces[pf][1]);
              const Vec<Number> v_rel = v_s - v_p;
              for (unsigned int i = 0; i < 2; ++i)
                {
                  if (rates)
                    sums.gap_rate[i] -= psi[i] * (v_rel * normal) * JxW;
                  if (friction)
                    sums.slip_rate[i] +=
                      psi[i] * (v_rel * SegmentGeometry::rotate(normal)) * JxW;
                }
            }
          // tangential traction z_t = sum_j psi_j lambda_t,j t_j on both
          // sides; the normal one along the nodal normals for approximate
          // Jacobians
          const Vec<Number> z_t = Number(psi[0] * m.lambda_t[0]) * m.t0 +
                                  Number(psi[1] * m.lambda_t[1]) * m.t1;
          const Vec<Number> z_n = Number(psi[0] * m.lambda[0]) * m.n0 +
                                  Number(psi[1] * m.lambda[1]) * m.n1;
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int d = 0; d < 2; ++d)
              {
                const auto rs = s.dofs[face[i]][d];
                const auto rp = p.dofs[p.faces[pf][i]][d];
                if (!exact)
                  {
                    sums.normal_rows[rs] += N[i] * z_n[d] * JxW;
                    sums.normal_rows[rp] -= Np[i] * z_n[d] * JxW;
                  }
                if (friction)
                  {
                    sums.rows[rs] += N[i] * z_t[d] * JxW;
                    sums.rows[rp] -= Np[i] * z_t[d] * JxW;
                    const double ft = (z_t[d] * JxW).val();
                    sums.tangential_rows[rs] += N[i].val() * ft;
                    sums.tangential_rows[rp] -= Np[i].val() * ft;
                  }
              }
        }
    }

    // The directions w_j d(g_j / w_j)/du_i of the normal force (i over the
    // positions, j over the face's nodes) and their derivatives weighted
    // with the multipliers, hessian[i n + l] = sum_j lambda_j
    // d direction[i][j]/du_l. AD2 is a Fad of Fads in the positions that
    // the gaps depend on, `seeded` (indices i): its cost grows with the
    // square of their number.
    template <typename AD2, int dim, typename PairData>
    void
    exact_directions(
      const PairData    &pair,
      const unsigned int e,
      const std::vector<std::pair<const ContactSurface<dim> *, unsigned int>>
                                                 &nodes,
      const std::vector<unsigned int>            &seeded,
      const std::vector<types::global_dof_index> &unknowns,
      const TrialState                           &state,
      const QGauss<1>                            &gauss,
      const double                                minimum_covered_fraction,
      const std::array<double, 2>                &lambda,
      std::vector<std::array<double, 2>>         &direction,
      std::vector<double>                        &hessian)
    {
      using Inner                    = typename AD2::value_type;
      const auto        &s           = pair.secondary;
      const unsigned int n_positions = 2 * nodes.size();
      const unsigned int n_seeded    = seeded.size();
      MortarPatch<AD2>   m2;
      for (unsigned int k = 0, v = 0; k < nodes.size(); ++k)
        {
          auto &x = (nodes[k].first == &s ? m2.xs : m2.xp)[nodes[k].second];
          for (unsigned int d = 0; d < 2; ++d)
            {
              const unsigned int i = 2 * k + d;
              const double       value =
                nodes[k].first->reference[nodes[k].second][d] +
                state.u(unknowns[i]);
              if (v < n_seeded && seeded[v] == i)
                {
                  x[d] = AD2(n_seeded, v, Inner(n_seeded, v, value));
                  ++v;
                }
              else
                x[d] = AD2(value);
            }
        }
      set_face_geometry(s, e, true, m2);
      const auto f = weighted_gaps(
        pair,
        m2,
        mortar_segments(pair, e, m2, true, minimum_covered_fraction),
        gauss);
      AD2 ratio[2] = {AD2(0.), AD2(0.)};
      for (unsigned int j = 0; j < 2; ++j)
        if (scalar(f.weight[j]) > 0)
          ratio[j] = f.gap[j] / f.weight[j];
      for (unsigned int v = 0; v < n_seeded; ++v)
        {
          Inner d[2] = {Inner(0.), Inner(0.)};
          for (unsigned int j = 0; j < 2; ++j)
            {
              if (scalar(f.weight[j]) > 0 && v < unsigned(ratio[j].size()))
                d[j] = f.weight[j].val() * ratio[j].dx(v);
              direction[seeded[v]][j] = d[j].val();
            }
          for (unsigned int w = 0; w < n_seeded; ++w)
            {
              double h = 0;
              for (unsigned int j = 0; j < 2; ++j)
                if (d[j].size() > int(w))
                  h += lambda[j] * d[j].dx(w);
              hessian[seeded[v] * n_positions + seeded[w]] = h;
            }
        }
    }

    // The segments of face e with its candidates, their integrals summed
    // into `sums`
    template <typename AD, typename PairData>
    Segments<AD>
    integrate_segments(const PairData        &pair,
                       const unsigned int     e,
                       const MortarPatch<AD> &m,
                       const QGauss<1>       &gauss,
                       const bool             rates,
                       const bool             exact,
                       const double           minimum_covered_fraction,
                       SegmentSums<AD>       &sums)
    {
      for (unsigned int i = 0; i < 2; ++i)
        sums.gap[i] = sums.weight[i] = sums.gap_rate[i] = sums.slip_rate[i] =
          AD(0.);
      auto segments =
        mortar_segments(pair, e, m, exact, minimum_covered_fraction);
      for (unsigned int k = 0; k < segments.faces.size(); ++k)
        integrate_segment(pair,
                          e,
                          segments.faces[k],
                          m,
                          segments.bounds[k].first,
                          segments.bounds[k].second,
                          segments.dual,
                          gauss,
                          rates,
                          exact,
                          sums);
      return segments;
    }

    // The exact directions of the normal force and their derivatives
    // (exact_directions()), seeded in the positions of the secondary nodes
    // and of the primary nodes of the `covering_faces`: the gaps do not
    // depend on the others
    template <int dim, typename PairData>
    void
    exact_normal_directions(
      const PairData    &pair,
      const unsigned int e,
      const std::vector<std::pair<const ContactSurface<dim> *, unsigned int>>
                                                 &nodes,
      const std::vector<unsigned int>            &covering_faces,
      const std::vector<types::global_dof_index> &unknowns,
      const TrialState                           &state,
      const QGauss<1>                            &gauss,
      const double                                minimum_covered_fraction,
      const std::array<double, 2>                &lambda,
      std::vector<std::array<double, 2>>         &direction,
      std::vector<double>                        &hessian)
    {
      const auto            &s = pair.secondary;
      const auto            &p = pair.primary;
      std::set<unsigned int> covering;
      for (const unsigned int pf : covering_faces)
        covering.insert(p.faces[pf].begin(), p.faces[pf].end());
      std::vector<unsigned int> seeded;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        if (nodes[k].first == &s || covering.count(nodes[k].second) > 0)
          for (unsigned int d = 0; d < 2; ++d)
            seeded.push_back(2 * k + d);
      ContactAD::dispatch_second(seeded.size(), [&](const auto zero) {
        exact_directions<std::decay_t<decltype(zero)>>(pair,
                                                       e,
                                                       nodes,
                                                       seeded,
                                                       unknowns,
                                                       state,
                                                       gauss,
                                                       minimum_covered_fraction,
                                                       lambda,
                                                       direction,
                                                       hessian);
      });
    }

    // 'approximate': the directions w_j d(g_j / w_j)/du_i of the normal
    // force from the exact face geometry, without their derivatives
    template <typename AD, typename PairData>
    void
    approximate_directions(const PairData                     &pair,
                           const unsigned int                  e,
                           const MortarPatch<AD>              &m,
                           const QGauss<1>                    &gauss,
                           const double                        minimum_fraction,
                           std::vector<std::array<double, 2>> &direction)
    {
      const unsigned int n_positions = direction.size();
      MortarPatch<AD>    exact_patch = m;
      set_face_geometry(pair.secondary, e, true, exact_patch);
      const auto f = weighted_gaps(
        pair,
        exact_patch,
        mortar_segments(pair, e, exact_patch, true, minimum_fraction),
        gauss);
      for (unsigned int j = 0; j < 2; ++j)
        if (f.weight[j].val() > 0)
          {
            const double ratio = f.gap[j].val() / f.weight[j].val();
            for (unsigned int i = 0; i < n_positions; ++i)
              direction[i][j] =
                (f.gap[j].size() > int(i) ? f.gap[j].dx(i) : 0.) -
                ratio * (f.weight[j].size() > int(i) ? f.weight[j].dx(i) : 0.);
          }
    }

    // The rows of the segment sums (friction and, approximate, the normal
    // force) into `forces`, the face's gaps, weights and rates into the
    // pair's nodes
    template <typename AD, typename PairData, typename PatchForces>
    void
    add_segment_sums(PairData                                   &pair,
                     const unsigned int                          e,
                     const SegmentSums<AD>                      &sums,
                     const std::vector<types::global_dof_index> &unknowns,
                     PatchForces                                &forces)
    {
      const auto &face = pair.secondary.faces[e];
      for (const auto &r : sums.rows)
        forces.add(r.first,
                   r.second.val(),
                   ContactAD::derivatives(r.second, unknowns));
      for (const auto &r : sums.tangential_rows)
        forces.add_tangential(r.first, r.second);
      for (unsigned int i = 0; i < 2; ++i)
        {
          ContactAD::add_to(pair.gap[face[i]], sums.gap[i], unknowns);
          ContactAD::add_to(pair.weight[face[i]], sums.weight[i], unknowns);
          ContactAD::add_to(pair.gap_rate[face[i]], sums.gap_rate[i], unknowns);
          ContactAD::add_to(pair.slip_rate[face[i]][0],
                            sums.slip_rate[i],
                            unknowns);
        }
    }
  } // namespace

  template <int dim>
  void
  MortarContact<dim>::assemble_patch(PairData          &pair,
                                     const unsigned int e,
                                     const TrialState  &state,
                                     PatchForces       &forces)
  {
    if (pair.secondary.degree == 2)
      return assemble_quadratic_patch(pair, e, state, forces);
    const auto unknowns = patch_unknowns(pair, e, pair.candidates[e]);
    ContactAD::dispatch(unknowns.size(), [&](const auto zero) {
      assemble_patch_ad<std::decay_t<decltype(zero)>>(pair,
                                                      e,
                                                      state,
                                                      unknowns,
                                                      forces);
    });
  }



  template <int dim>
  template <typename AD>
  void
  MortarContact<dim>::assemble_patch_ad(
    PairData                                   &pair,
    const unsigned int                          e,
    const TrialState                           &state,
    const std::vector<types::global_dof_index> &unknowns,
    PatchForces                                &forces)
  {
    const auto &s     = pair.secondary;
    const auto &p     = pair.primary;
    const auto &face  = s.faces[e];
    const bool  exact = this->complementarity.exact_jacobian;

    // independent variables: positions of the secondary nodes of the face
    // and their neighbours, of the primary nodes, then the multipliers
    ContactAD::NodeVariables<dim, AD> variables(unknowns, state);
    MortarPatch<AD>                   m;
    const unsigned int                before = s.neighbour(face[0], e);
    const unsigned int                after  = s.neighbour(face[1], e);
    std::vector<std::pair<const ContactSurface<dim> *, unsigned int>> nodes;
    for (const unsigned int node : {before, face[0], face[1], after})
      if (node != ContactSurface<dim>::invalid)
        {
          variables.add(s, node, m.xs[node], m.vs[node]);
          nodes.emplace_back(&s, node);
        }
    for (const unsigned int node : primary_nodes<dim>(pair, pair.candidates[e]))
      {
        variables.add(p, node, m.xp[node], m.vp[node]);
        nodes.emplace_back(&p, node);
      }
    const unsigned int n_positions = 2 * nodes.size();
    m.lambda[0]                    = variables.multiplier();
    m.lambda[1]                    = variables.multiplier();
    m.lambda_t[0]                  = variables.multiplier();
    m.lambda_t[1]                  = variables.multiplier();
    set_face_geometry(s, e, exact, m);

    const QGauss<1> gauss(quadrature_points);
    // (the first rate of a held node, the velocity-level condition)
    const bool rates = this->complementarity.holds_contact() && state.dynamic;
    SegmentSums<AD> sums;
    const auto      segments = integrate_segments(pair,
                                             e,
                                             m,
                                             gauss,
                                             rates,
                                             exact,
                                             minimum_covered_fraction,
                                             sums);

    // The normal force is -sum_j lambda_j w_j d(g_j / w_j)/du, with this
    // face's weighted gap g_j and weight w_j of node j: the derivative of
    // the normalized gaps that the complementarity condition enforces, so
    // that a held gap does no work (to second order in the difference of
    // the faces' normalized gaps at a node), and a uniform penetration
    // does not act on the length of the face. Its Jacobian needs second
    // derivatives (or, approximate, the nodal-normal traction's).
    const std::array<double, 2> lambda{{m.lambda[0].val(), m.lambda[1].val()}};
    // direction[i][j] = w_j d(g_j / w_j)/du_i, with its derivatives
    std::vector<std::array<double, 2>> direction(n_positions, {{0., 0.}});
    std::vector<double> hessian(exact ? n_positions * n_positions : 0);
    if (exact && !segments.faces.empty())
      exact_normal_directions(pair,
                              e,
                              nodes,
                              segments.faces,
                              unknowns,
                              state,
                              gauss,
                              minimum_covered_fraction,
                              lambda,
                              direction,
                              hessian);
    else if (!exact)
      approximate_directions(pair,
                             e,
                             m,
                             gauss,
                             minimum_covered_fraction,
                             direction);
    // (approximate: the derivatives of the nodal-normal traction)
    forces.add_normal_rows(unknowns,
                           lambda,
                           direction,
                           hessian,
                           [&](const unsigned int                 i,
                               typename PatchForces::Derivatives &d) {
                             if (exact)
                               return;
                             const auto r = sums.normal_rows.find(unknowns[i]);
                             if (r != sums.normal_rows.end())
                               for (unsigned int l = 0;
                                    l < n_positions &&
                                    l < unsigned(r->second.size());
                                    ++l)
                                 if (r->second.dx(l) != 0)
                                   d.emplace_back(unknowns[l], r->second.dx(l));
                           });
    add_segment_sums(pair, e, sums, unknowns, forces);
  }

  template class MortarContact<2>;
  template class MortarContact<3>;
} // namespace ContactDynamics

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>

#include <contact_dynamics/parameters.h>
#include <contact_dynamics/scenes/quadratic_geometry.h>

#include <array>
#include <cmath>

namespace ContactDynamics
{
  namespace
  {
    template <int dim>
    std::string
    point_text(const Point<dim> &p)
    {
      std::string text = "(";
      for (unsigned int d = 0; d < dim; ++d)
        text += (d > 0 ? " " : "") + format_number(p[d]);
      return text + ")";
    }

    // the quadratic 1-D basis on the nodes 0, 1/2, 1 and its derivative
    std::array<double, 3>
    basis_1d(const double x)
    {
      return {{(1 - x) * (1 - 2 * x), 4 * x * (1 - x), x * (2 * x - 1)}};
    }

    std::array<double, 3>
    derivative_1d(const double x)
    {
      return {{4 * x - 3, 4 - 8 * x, 4 * x - 1}};
    }
  } // namespace



  template <int dim>
  QuadraticGeometry<dim>::QuadraticGeometry(
    std::vector<std::vector<Point<dim>>> nodes,
    const std::string                   &source)
    : coarse_nodes(std::move(nodes))
    , element(std::make_unique<FE_Q<dim>>(2))
  {
    // node i's 1-D factors: at 0, 1/2 or 1 in each direction
    for (const Point<dim> &p : element->get_unit_support_points())
      {
        std::array<unsigned int, dim> factor;
        for (unsigned int d = 0; d < dim; ++d)
          factor[d] = static_cast<unsigned int>(std::lround(2 * p[d]));
        node_factor.push_back(factor);
      }
    // A mid-side node pulled past its neighbours folds the cell where the
    // corners alone would not show it, first at the nodes and the edges:
    // Gauss-Lobatto points (the nodes among them) and Gauss points.
    std::vector<Point<dim>> checked = QGaussLobatto<dim>(5).get_points();
    const QGauss<dim> gauss(3);
    checked.insert(checked.end(),
                   gauss.get_points().begin(),
                   gauss.get_points().end());
    for (const auto &cell_nodes : coarse_nodes)
      {
        AssertThrow(cell_nodes.size() == node_factor.size(),
                    ExcInternalError());
        for (const Point<dim> &xi : checked)
          {
            const double det = determinant(jacobian(cell_nodes, xi));
            AssertThrow(det > 0,
                        ExcMessage(
                          source + "has a second-order cell (corner " +
                          point_text(cell_nodes[0]) +
                          ") folded by its mid-side or centre nodes: its "
                          "Jacobian determinant is " +
                          format_number(det) + " <= 0 at " +
                          point_text(map(cell_nodes, xi)) +
                          ". Move those nodes back between the corners (or "
                          "mesh the curved boundary finer)."));
          }
      }
  }



  template <int dim>
  QuadraticGeometry<dim>::~QuadraticGeometry() = default;



  template <int dim>
  Point<dim>
  QuadraticGeometry<dim>::map(const std::vector<Point<dim>> &nodes,
                              const Point<dim>              &xi) const
  {
    // the tensor-product basis by its 1-D factors (FE_Q::shape_value per
    // node and point would cost about as much as the cell's assembly)
    std::array<std::array<double, 3>, dim> L;
    for (unsigned int d = 0; d < dim; ++d)
      L[d] = basis_1d(xi[d]);
    Point<dim> x;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        double N = 1;
        for (unsigned int d = 0; d < dim; ++d)
          N *= L[d][node_factor[i][d]];
        x += N * nodes[i];
      }
    return x;
  }



  template <int dim>
  Tensor<2, dim>
  QuadraticGeometry<dim>::jacobian(const std::vector<Point<dim>> &nodes,
                                   const Point<dim>              &xi) const
  {
    std::array<std::array<double, 3>, dim> L, dL;
    for (unsigned int d = 0; d < dim; ++d)
      {
        L[d]  = basis_1d(xi[d]);
        dL[d] = derivative_1d(xi[d]);
      }
    Tensor<2, dim> J;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      for (unsigned int k = 0; k < dim; ++k)
        {
          double dN = 1;
          for (unsigned int d = 0; d < dim; ++d)
            dN *= (d == k ? dL[d] : L[d])[node_factor[i][d]];
          for (unsigned int c = 0; c < dim; ++c)
            J[c][k] += nodes[i][c] * dN;
        }
    return J;
  }



  template <int dim>
  std::vector<Point<dim>>
  QuadraticGeometry<dim>::support_points(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    if (cell->level() == 0)
      {
        AssertIndexRange(cell->index(), coarse_nodes.size());
        Assert(coarse_nodes[cell->index()][0].distance(cell->vertex(0)) <=
                 1e-12 * (1 + cell->diameter()),
               ExcMessage("The geometry belongs to another coarse mesh."));
        return coarse_nodes[cell->index()];
      }
    // the cell's support points in the reference cell of its coarse ancestor
    std::vector<Point<dim>> xi       = element->get_unit_support_points();
    auto                    ancestor = cell;
    while (ancestor->level() > 0)
      {
        const auto         parent = ancestor->parent();
        const unsigned int child  = parent->child_iterator_to_index(ancestor);
        for (Point<dim> &p : xi)
          p = GeometryInfo<dim>::child_to_cell_coordinates(p, child);
        ancestor = parent;
      }
    AssertIndexRange(ancestor->index(), coarse_nodes.size());
    const auto &nodes = coarse_nodes[ancestor->index()];
    for (Point<dim> &p : xi)
      p = map(nodes, p);
    return xi;
  }



  template class QuadraticGeometry<2>;
  template class QuadraticGeometry<3>;
} // namespace ContactDynamics

// The curved geometry a mesh file gives its cells through their mid-side,
// face-centre and cell-centre nodes (Gmsh's second-order elements): each
// coarse cell is the image of the reference cell under the tri-quadratic
// (bi-quadratic in 2-D) interpolation of its 3^dim nodes, and a refined cell
// is the image of its part of the reference cell, so that refinement follows
// the curved geometry exactly.
#ifndef contact_dynamics_scenes_quadratic_geometry_h
#define contact_dynamics_scenes_quadratic_geometry_h

#include <deal.II/grid/tria.h>

#include <array>
#include <memory>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class FiniteElement;
}

namespace ContactDynamics
{
  using namespace dealii;

  template <int dim>
  class QuadraticGeometry
  {
  public:
    /**
     * `nodes[c]` are the 3^dim nodes of the coarse cell c (level 0, index c)
     * in deal.II's hierarchic order (vertices, lines, faces, interior), as
     * MappingQ(2) and FE_Q(2) number their support points. Throws a message
     * that begins with `source` (a subject: "The mesh file 'x' ") if a
     * cell's map folds (a Jacobian determinant <= 0 at
     * a vertex or a Gauss point).
     */
    QuadraticGeometry(std::vector<std::vector<Point<dim>>> nodes,
                      const std::string                   &source);
    ~QuadraticGeometry();

    /**
     * The 3^dim support points of a MappingQ(2) on any cell of the
     * triangulation whose coarse cells these are: the coarse cell's nodes,
     * or, on a refined cell, the coarse map at the cell's own reference
     * support points.
     */
    std::vector<Point<dim>>
    support_points(
      const typename Triangulation<dim>::cell_iterator &cell) const;

    /** The sum of all nodes' coordinates (a checkpoint's signature). */
    double
    node_sum() const
    {
      double sum = 0;
      for (const auto &cell : coarse_nodes)
        for (const auto &p : cell)
          for (unsigned int d = 0; d < dim; ++d)
            sum += p[d];
      return sum;
    }

    unsigned int
    n_coarse_cells() const
    {
      return coarse_nodes.size();
    }

    /** The map of a coarse cell with these nodes at the reference point. */
    Point<dim>
    map(const std::vector<Point<dim>> &nodes, const Point<dim> &xi) const;

    /** Its Jacobian d x / d xi there. */
    Tensor<2, dim>
    jacobian(const std::vector<Point<dim>> &nodes, const Point<dim> &xi) const;

  private:
    std::vector<std::vector<Point<dim>>>     coarse_nodes;
    std::unique_ptr<FiniteElement<dim, dim>> element; // FE_Q(2)
    // per node, the index of its 1-D basis function (at 0, 1/2, 1) in each
    // direction
    std::vector<std::array<unsigned int, dim>> node_factor;
  };
} // namespace ContactDynamics

#endif

#include <deal.II/fe/fe_q.h>

#include <contact_dynamics/mechanics/discretization.h>
#include <contact_dynamics/mechanics/geometry_mapping.h>

namespace ContactDynamics
{
  template <int dim>
  void
  Discretization<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Polynomial degree",
      std::to_string(Discretization<dim>().polynomial_degree),
      Patterns::Integer(1, 2),
      "Degree p of the Lagrange elements of the bodies, 1 or 2: FE_Q(p) for "
      "the displacement (2: 9-node quadrilaterals, 27-node hexahedra) with "
      "a mapping of the same degree, so that with 2 the cells at the curved "
      "surfaces of the built-in scenes (the Hertz cylinder and sphere, the "
      "ironing tools) are curved as well, and so are the cells of a Gmsh "
      "mesh of second order (9-node quadrilaterals, 27-node hexahedra: "
      "their mid-side and centre nodes give the geometry; with 1 those "
      "nodes are ignored and the cells are straight). On the same mesh degree 2 has about 2^dim "
      "times the unknowns of degree 1 (4 in 2-D, 8 in 3-D) and 1.8 (2-D) or "
      "2.4 (3-D) times the matrix entries per row (doc/accuracy-vs-cost.md "
      "says what each degree costs and buys). One degree for all bodies. "
      "With 2, contact works against rigid obstacles (Contact/Rigid "
      "obstacles; every node of a contact face, mid-side and centre nodes "
      "too, is a contact node, both formulations), between two meshed "
      "surfaces (3-node curved faces in 2-D, 9-node ones in 3-D; both "
      "formulations, with or without friction), and with Mesh "
      "refinement/Adapt to contact.");
  }

  template <int dim>
  void
  Discretization<dim>::parse_parameters(ParameterHandler &prm)
  {
    polynomial_degree = prm.get_integer("Polynomial degree");
  }

  template <int dim>
  void
  Discretization<dim>::create(const unsigned int n_extra)
  {
    const FE_Q<dim> q(polynomial_degree);
    element = n_extra > 0 ?
                std::make_unique<FESystem<dim>>(q, dim, q, n_extra) :
                std::make_unique<FESystem<dim>>(q, dim);
    if (polynomial_degree == 1)
      cell_mapping = std::make_unique<MappingQ<dim>>(1);
    else
      cell_mapping = std::make_unique<GeometryMapping<dim>>();
  }

  template <int dim>
  void
  Discretization<dim>::set_geometry(
    std::shared_ptr<const QuadraticGeometry<dim>> geometry)
  {
    Assert(cell_mapping, ExcMessage("create() was not called"));
    if (auto *curved = dynamic_cast<GeometryMapping<dim> *>(cell_mapping.get()))
      curved->set_geometry(std::move(geometry));
  }

  template class Discretization<2>;
  template class Discretization<3>;
} // namespace ContactDynamics

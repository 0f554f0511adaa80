// The finite element of the bodies and the mapping of their cells: the
// polynomial degree of the displacement and of the geometry.
#ifndef contact_dynamics_mechanics_discretization_h
#define contact_dynamics_mechanics_discretization_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>

#include <memory>

namespace ContactDynamics
{
  using namespace dealii;

  template <int dim>
  class QuadraticGeometry;

  /**
   * FE_Q(p) for every displacement component and for the contact
   * multipliers, with a mapping of the same degree: with p = 2 the cells at
   * curved surfaces of the scenes (their manifolds, or the nodes of a mesh
   * file's second-order cells) are curved in the geometry too, not only in
   * the unknowns. One degree for the run.
   */
  template <int dim>
  class Discretization
  {
  public:
    /** "Polynomial degree" in the current subsection. */
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** The element: dim displacement components, then `n_extra` more. */
    void
    create(const unsigned int n_extra);

    /**
     * With degree 2, the cells' curved geometry from the mesh file's nodes
     * (null: from the scene's manifolds); degree 1 keeps straight cells
     * between the vertices. Call after create() and after every
     * (re)creation of the coarse mesh.
     */
    void
    set_geometry(std::shared_ptr<const QuadraticGeometry<dim>> geometry);

    unsigned int
    degree() const
    {
      return polynomial_degree;
    }

    const FESystem<dim> &
    fe() const
    {
      Assert(element, ExcMessage("create() was not called"));
      return *element;
    }

    const Mapping<dim> &
    mapping() const
    {
      Assert(cell_mapping, ExcMessage("create() was not called"));
      return *cell_mapping;
    }

  private:
    unsigned int                   polynomial_degree = 1;
    std::unique_ptr<FESystem<dim>> element;
    std::unique_ptr<Mapping<dim>>  cell_mapping;
  };
} // namespace ContactDynamics

#endif

// The mapping of degree 2: deal.II's MappingQ(2), which places its support
// points on the scene's manifolds, or, where the scene's mesh file gives
// the cells' curved geometry by their nodes, takes them from there.
#ifndef contact_dynamics_mechanics_geometry_mapping_h
#define contact_dynamics_mechanics_geometry_mapping_h

#include <deal.II/fe/mapping_q.h>

#include <contact_dynamics/scenes/quadratic_geometry.h>

#include <memory>

namespace ContactDynamics
{
  using namespace dealii;

  template <int dim>
  class GeometryMapping : public MappingQ<dim>
  {
  public:
    GeometryMapping();

    /**
     * From now on the support points of every cell come from `nodes`
     * (null: from the manifolds again). The triangulation's vertices of a
     * refined cell then stay where a flat refinement put them: positions
     * come from the mapping, not from cell->vertex().
     */
    void
    set_geometry(std::shared_ptr<const QuadraticGeometry<dim>> nodes);

    std::unique_ptr<Mapping<dim>>
    clone() const override;

    boost::container::small_vector<Point<dim>,
                                   GeometryInfo<dim>::vertices_per_cell>
    get_vertices(
      const typename Triangulation<dim>::cell_iterator &cell) const override;

    bool
    preserves_vertex_locations() const override;

  protected:
    std::vector<Point<dim>>
    compute_mapping_support_points(
      const typename Triangulation<dim>::cell_iterator &cell) const override;

  private:
    std::shared_ptr<const QuadraticGeometry<dim>> geometry;
  };
} // namespace ContactDynamics

#endif

#include <contact_dynamics/mechanics/geometry_mapping.h>

namespace ContactDynamics
{
  template <int dim>
  GeometryMapping<dim>::GeometryMapping()
    : MappingQ<dim>(2)
  {}



  template <int dim>
  void
  GeometryMapping<dim>::set_geometry(
    std::shared_ptr<const QuadraticGeometry<dim>> nodes)
  {
    geometry = std::move(nodes);
  }



  template <int dim>
  std::unique_ptr<Mapping<dim>>
  GeometryMapping<dim>::clone() const
  {
    return std::make_unique<GeometryMapping<dim>>(*this);
  }



  template <int dim>
  boost::container::small_vector<Point<dim>,
                                 GeometryInfo<dim>::vertices_per_cell>
  GeometryMapping<dim>::get_vertices(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    if (!geometry)
      return MappingQ<dim>::get_vertices(cell);
    const std::vector<Point<dim>> points = geometry->support_points(cell);
    return {points.begin(), points.begin() + cell->n_vertices()};
  }



  template <int dim>
  bool
  GeometryMapping<dim>::preserves_vertex_locations() const
  {
    return !geometry && MappingQ<dim>::preserves_vertex_locations();
  }



  template <int dim>
  std::vector<Point<dim>>
  GeometryMapping<dim>::compute_mapping_support_points(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    return geometry ? geometry->support_points(cell) :
                      MappingQ<dim>::compute_mapping_support_points(cell);
  }



  template class GeometryMapping<2>;
  template class GeometryMapping<3>;
} // namespace ContactDynamics

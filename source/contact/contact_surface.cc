#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe.h>

#include <contact_dynamics/contact/clipping_geometry.h>
#include <contact_dynamics/contact/contact_surface.h>
#include <contact_dynamics/parallel.h>

#include <algorithm>
#include <map>

namespace ContactDynamics
{
  namespace
  {
    /**
     * The records of the faces of the locally owned cells on the surfaces
     * `ids`, oriented there: the nodes' coordinates, their dofs, depth,
     * and whether the face's normal by its node order points into the cell
     * (then the order is reversed).
     */
    template <int dim>
    Message
    owned_face_records(const DoFHandler<dim>                 &dof_handler,
                       const std::vector<types::boundary_id> &ids,
                       const unsigned int                     n_node_components)
    {
      const auto            &fe  = dof_handler.get_fe();
      constexpr unsigned int n_v = ContactSurface<dim>::nodes_per_face;
      Message                records;
      std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                std::find(ids.begin(),
                          ids.end(),
                          cell->face(f)->boundary_id()) != ids.end())
              {
                cell->get_dof_indices(cell_dofs);
                std::array<unsigned int, n_v> v;
                for (unsigned int i = 0; i < n_v; ++i)
                  v[i] = GeometryInfo<dim>::face_to_cell_vertices(f, i);
                const Tensor<1, dim> t =
                  cell->vertex(v[1]) - cell->vertex(v[0]);
                Tensor<1, dim> n;
                if constexpr (dim == 2)
                  {
                    n[0] = t[1];
                    n[1] = -t[0];
                  }
                else
                  n = cross_product_3d(t,
                                       cell->vertex(v[2]) - cell->vertex(v[0]));
                for (const unsigned int cell_vertex : v)
                  for (unsigned int d = 0; d < dim; ++d)
                    records.write(cell->vertex(cell_vertex)[d]);
                for (const unsigned int cell_vertex : v)
                  for (unsigned int c = 0; c < n_node_components; ++c)
                    records.write_index(
                      cell_dofs[fe.component_to_system_index(c, cell_vertex)]);
                records.write(cell->measure() / cell->face(f)->measure());
                records.write_index(
                  n * (cell->face(f)->center() - cell->center()) < 0);
              }
      return records;
    }

    // Adds the integrals of the nodes' shape functions over a face in the
    // reference configuration: a segment's,
    void
    add_face_weights(const std::vector<Point<2>>       &reference,
                     const std::array<unsigned int, 2> &face,
                     std::vector<double>               &weights)
    {
      const double length = reference[face[0]].distance(reference[face[1]]);
      weights[face[0]] += length / 2;
      weights[face[1]] += length / 2;
    }

    // a bilinear quadrilateral's
    void
    add_face_weights(const std::vector<Point<3>>       &reference,
                     const std::array<unsigned int, 4> &face,
                     std::vector<double>               &weights)
    {
      std::array<Tensor<1, 3>, 4> x;
      for (unsigned int v = 0; v < 4; ++v)
        for (unsigned int d = 0; d < 3; ++d)
          x[v][d] = reference[face[v]][d];
      for (const auto &q : ClippingGeometry::face_points(x))
        {
          const auto N = ClippingGeometry::shape(q.xi, q.eta);
          for (unsigned int v = 0; v < 4; ++v)
            weights[face[v]] += q.weight * N[v];
        }
    }
  } // namespace

  template <int dim>
  void
  ContactSurface<dim>::build(const DoFHandler<dim>                 &dof_handler,
                             const std::vector<types::boundary_id> &ids,
                             const unsigned int n_node_components)
  {
    reference.clear();
    dofs.clear();
    faces.clear();
    node_faces.clear();
    reference_weight.clear();
    depth.clear();

    // The faces of the locally owned cells, oriented there, then gathered:
    // every process gets the whole surface, O(surface) data, also from a
    // distributed mesh. A record is the nodes' coordinates, their dofs,
    // depth, and whether the face's normal by its node order points into
    // the cell (then the order is reversed).
    constexpr unsigned int n_v = nodes_per_face;
    // nodes are numbered in the order they first appear; a node is known
    // by its first dof
    std::map<types::global_dof_index, unsigned int> dof_to_node;
    const auto read_face = [&](Message &record) {
      std::array<Point<dim>, n_v> x;
      for (auto &point : x)
        for (unsigned int d = 0; d < dim; ++d)
          point[d] = record.read();
      std::array<std::vector<types::global_dof_index>, n_v> node_dofs;
      for (auto &list : node_dofs)
        for (unsigned int c = 0; c < n_node_components; ++c)
          list.push_back(record.read_index());
      std::array<unsigned int, n_v> face_nodes;
      for (unsigned int v = 0; v < n_v; ++v)
        {
          auto it = dof_to_node.find(node_dofs[v][0]);
          if (it == dof_to_node.end())
            {
              it = dof_to_node.emplace(node_dofs[v][0], reference.size()).first;
              reference.push_back(x[v]);
              dofs.push_back(node_dofs[v]);
              node_faces.emplace_back();
            }
          face_nodes[v] = it->second;
        }
      depth.push_back(record.read());
      // reversed: in 3-D, exchanging nodes 1 and 2 exchanges xi and eta
      if (record.read_index() != 0)
        std::swap(face_nodes[0 + (dim == 3)], face_nodes[1 + (dim == 3)]);
      for (const unsigned int node : face_nodes)
        node_faces[node].push_back(faces.size());
      faces.push_back(face_nodes);
    };
    gather_messages(dof_handler.get_communicator(),
                    owned_face_records(dof_handler, ids, n_node_components),
                    [&](Message &part) {
                      while (!part.at_end())
                        read_face(part);
                    });

    reference_weight.assign(reference.size(), 0.);
    for (const auto &face : faces)
      add_face_weights(reference, face, reference_weight);
    if (dim == 2)
      for (const auto &nf : node_faces)
        AssertThrow(nf.size() <= 2,
                    ExcMessage("A contact surface node belongs to more than "
                               "two faces: the surface must be a curve."));
  }

  template <int dim>
  unsigned int
  ContactSurface<dim>::neighbour(const unsigned int node,
                                 const unsigned int face) const
  {
    Assert(dim == 2, ExcNotImplemented());
    for (const unsigned int f : node_faces[node])
      if (f != face)
        return faces[f][0] == node ? faces[f][1] : faces[f][0];
    return invalid;
  }

  template class ContactSurface<2>;
  template class ContactSurface<3>;
} // namespace ContactDynamics

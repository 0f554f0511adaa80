#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping_q.h>

#include <contact_dynamics/contact/clipping_geometry.h>
#include <contact_dynamics/contact/contact_surface.h>
#include <contact_dynamics/contact/quadratic_face.h>
#include <contact_dynamics/parallel.h>

#include <algorithm>
#include <map>
#include <memory>

namespace ContactDynamics
{
  namespace
  {
    /**
     * Per face of the reference cell, the indices (in the base element)
     * of the nodes of a face of degree 2 in the order of
     * QuadraticFace::node_coordinates(), and their unit-cell points.
     */
    template <int dim>
    std::vector<std::vector<std::pair<unsigned int, Point<dim>>>>
    quadratic_face_nodes(const FiniteElement<dim> &base)
    {
      const auto &support = base.get_unit_support_points();
      std::vector<std::vector<std::pair<unsigned int, Point<dim>>>> result(
        GeometryInfo<dim>::faces_per_cell);
      for (unsigned int f = 0; f < GeometryInfo<dim>::faces_per_cell; ++f)
        for (const auto &s : QuadraticFace::node_coordinates<dim>())
          {
            // the bilinear map of the face's vertices
            Point<dim> p;
            for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_face;
                 ++v)
              {
                double N = 1;
                for (unsigned int k = 0; k < dim - 1; ++k)
                  N *= (v >> k) & 1 ? s[k] : 1 - s[k];
                p += N * GeometryInfo<dim>::unit_cell_vertex(
                           GeometryInfo<dim>::face_to_cell_vertices(f, v));
              }
            unsigned int i = 0;
            while (i < support.size() && support[i].distance(p) > 1e-12)
              ++i;
            AssertThrow(i < support.size(), ExcInternalError());
            result[f].emplace_back(i, p);
          }
      return result;
    }

    /**
     * The records of the faces of the locally owned cells on the surfaces
     * `ids`, oriented there: the nodes' coordinates, their dofs, depth,
     * and whether the face's normal by its vertex order points into the
     * cell (then the order is reversed). With degree 2 every node of the
     * face, placed by a mapping of that degree.
     */
    template <int dim>
    Message
    owned_face_records(const DoFHandler<dim>                 &dof_handler,
                       const Mapping<dim>                    *cell_mapping,
                       const std::vector<types::boundary_id> &ids,
                       const unsigned int                     n_node_components)
    {
      const auto            &fe        = dof_handler.get_fe();
      constexpr unsigned int n_v       = ContactSurface<dim>::nodes_per_face;
      const bool             quadratic = fe.degree == 2;
      const auto nodes = quadratic ? quadratic_face_nodes(fe.base_element(0)) :
                                     decltype(quadratic_face_nodes(fe)){};
      // (only degree 2 places nodes inside the cell's vertices)
      const std::unique_ptr<Mapping<dim>> own_mapping =
        quadratic && !cell_mapping ? std::make_unique<MappingQ<dim>>(2) :
                                     nullptr;
      const Mapping<dim>                  *mapping = !quadratic ? nullptr :
                                                     own_mapping ? own_mapping.get() :
                                                                   cell_mapping;
      Message                              records;
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
                // a refined cell of a mesh file's second-order cells has its
                // vertices where the mapping puts them, not in the mesh
                const auto vertex   = mapping ?
                                        mapping->get_vertices(cell) :
                                        decltype(mapping->get_vertices(cell))();
                const auto position = [&](const unsigned int i) {
                  return mapping ? vertex[i] : cell->vertex(i);
                };
                std::array<unsigned int, n_v> v;
                for (unsigned int i = 0; i < n_v; ++i)
                  v[i] = GeometryInfo<dim>::face_to_cell_vertices(f, i);
                const Tensor<1, dim> t = position(v[1]) - position(v[0]);
                Tensor<1, dim>       n;
                if constexpr (dim == 2)
                  {
                    n[0] = t[1];
                    n[1] = -t[0];
                  }
                else
                  n = cross_product_3d(t, position(v[2]) - position(v[0]));
                // (node index in the base element, position)
                std::vector<std::pair<unsigned int, Point<dim>>> face_nodes;
                for (const unsigned int cell_vertex : v)
                  face_nodes.emplace_back(cell_vertex, position(cell_vertex));
                if (quadratic)
                  for (unsigned int k = n_v; k < nodes[f].size(); ++k)
                    face_nodes.emplace_back(
                      nodes[f][k].first,
                      mapping->transform_unit_to_real_cell(cell,
                                                           nodes[f][k].second));
                for (const auto &node : face_nodes)
                  for (unsigned int d = 0; d < dim; ++d)
                    records.write(node.second[d]);
                for (const auto &node : face_nodes)
                  for (unsigned int c = 0; c < n_node_components; ++c)
                    records.write_index(
                      cell_dofs[fe.component_to_system_index(c, node.first)]);
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

    /**
     * The integrals of N_a over the curved face of degree 2 whose nodes
     * are at x; three Gauss points per direction integrate the quadratic
     * N_a times a smooth area element.
     */
    template <int dim>
    std::array<double, QuadraticFace::n_nodes<dim>>
    quadratic_face_integrals(
      const std::array<Tensor<1, dim>, QuadraticFace::n_nodes<dim>> &x)
    {
      std::array<double, QuadraticFace::n_nodes<dim>> integrals{};
      const QGauss<dim - 1>                           quadrature(3);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const auto   shape = QuadraticFace::shape<dim>(quadrature.point(q));
          const double JxW   = quadrature.weight(q) *
                             QuadraticFace::area_element<dim>(shape.dN, x);
          for (unsigned int a = 0; a < integrals.size(); ++a)
            integrals[a] += shape.N[a] * JxW;
        }
      return integrals;
    }
  } // namespace

  template <int dim>
  double
  ContactSurface<dim>::current_weight(
    const unsigned int                   node,
    const TrilinosWrappers::MPI::Vector &u) const
  {
    Assert(degree == 2, ExcNotImplemented());
    double weight = 0;
    for (const unsigned int f : node_faces[node])
      {
        std::array<Tensor<1, dim>, QuadraticFace::n_nodes<dim>> x;
        for (unsigned int a = 0; a < x.size(); ++a)
          x[a] = position(face_nodes[f][a], u);
        const auto integrals = quadratic_face_integrals<dim>(x);
        for (unsigned int a = 0; a < x.size(); ++a)
          if (face_nodes[f][a] == node)
            weight += integrals[a];
      }
    return weight;
  }

  template <int dim>
  void
  ContactSurface<dim>::build(const DoFHandler<dim>                 &dof_handler,
                             const std::vector<types::boundary_id> &ids,
                             const unsigned int  n_node_components,
                             const Mapping<dim> *mapping)
  {
    reference.clear();
    dofs.clear();
    faces.clear();
    face_nodes.clear();
    node_faces.clear();
    reference_weight.clear();
    depth.clear();

    // The faces of the locally owned cells, oriented there, then gathered:
    // every process gets the whole surface, O(surface) data, also from a
    // distributed mesh. A record is the nodes' coordinates, their dofs,
    // depth, and whether the face's normal by its node order points into
    // the cell (then the order is reversed).
    degree = dof_handler.get_fe().degree;
    AssertThrow(degree <= 2, ExcNotImplemented());
    const unsigned int n_v =
      degree == 1 ? nodes_per_face : QuadraticFace::n_nodes<dim>;
    // nodes are numbered in the order they first appear; a node is known
    // by its first dof
    std::map<types::global_dof_index, unsigned int> dof_to_node;
    const auto read_face = [&](Message &record) {
      std::vector<Point<dim>> x(n_v);
      for (auto &point : x)
        for (unsigned int d = 0; d < dim; ++d)
          point[d] = record.read();
      std::vector<std::vector<types::global_dof_index>> node_dofs(n_v);
      for (auto &list : node_dofs)
        for (unsigned int c = 0; c < n_node_components; ++c)
          list.push_back(record.read_index());
      std::vector<unsigned int> nodes(n_v);
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
          nodes[v] = it->second;
        }
      depth.push_back(record.read());
      // reversed: in 3-D, exchanging nodes 1 and 2 exchanges xi and eta
      if (record.read_index() != 0)
        for (const auto &[a, b] : QuadraticFace::reversal_swaps<dim>())
          if (b < n_v)
            std::swap(nodes[a], nodes[b]);
      for (const unsigned int node : nodes)
        node_faces[node].push_back(faces.size());
      std::array<unsigned int, nodes_per_face> vertices;
      std::copy(nodes.begin(),
                nodes.begin() + nodes_per_face,
                vertices.begin());
      faces.push_back(vertices);
      face_nodes.push_back(nodes);
    };
    gather_messages(
      dof_handler.get_communicator(),
      owned_face_records(dof_handler, mapping, ids, n_node_components),
      [&](Message &part) {
        while (!part.at_end())
          read_face(part);
      });

    reference_weight.assign(reference.size(), 0.);
    if (degree == 1)
      for (const auto &face : faces)
        add_face_weights(reference, face, reference_weight);
    else
      for (const auto &face : face_nodes)
        {
          std::array<Tensor<1, dim>, QuadraticFace::n_nodes<dim>> x;
          for (unsigned int a = 0; a < x.size(); ++a)
            x[a] = reference[face[a]];
          const auto integrals = quadratic_face_integrals<dim>(x);
          for (unsigned int a = 0; a < x.size(); ++a)
            reference_weight[face[a]] += integrals[a];
        }
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

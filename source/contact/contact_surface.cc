#include <deal.II/base/exceptions.h>

#include <deal.II/fe/fe.h>

#include <contact_dynamics/contact/contact_surface.h>

#include <algorithm>
#include <map>

namespace ContactDynamics
{
  template <int dim>
  void
  ContactSurface<dim>::build(const DoFHandler<dim>                 &dof_handler,
                             const std::vector<types::boundary_id> &ids,
                             const unsigned int n_node_components)
  {
    AssertThrow(dim == 2, ExcMessage("Contact is implemented in 2-D only."));
    const auto &fe = dof_handler.get_fe();
    reference.clear();
    dofs.clear();
    faces.clear();
    node_faces.clear();
    reference_weight.clear();
    depth.clear();

    std::map<unsigned int, unsigned int> vertex_to_node;
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            std::find(ids.begin(), ids.end(), cell->face(f)->boundary_id()) !=
              ids.end())
          {
            cell->get_dof_indices(cell_dofs);
            std::array<unsigned int, 2> face_nodes;
            for (unsigned int v = 0; v < 2; ++v)
              {
                const unsigned int cell_vertex =
                  GeometryInfo<dim>::face_to_cell_vertices(f, v);
                const unsigned int vertex = cell->vertex_index(cell_vertex);
                auto               it     = vertex_to_node.find(vertex);
                if (it == vertex_to_node.end())
                  {
                    it = vertex_to_node.emplace(vertex, reference.size()).first;
                    reference.push_back(cell->vertex(cell_vertex));
                    std::vector<types::global_dof_index> node_dofs;
                    for (unsigned int c = 0; c < n_node_components; ++c)
                      node_dofs.push_back(
                        cell_dofs[fe.component_to_system_index(c,
                                                               cell_vertex)]);
                    dofs.push_back(node_dofs);
                    node_faces.emplace_back();
                  }
                face_nodes[v] = it->second;
              }
            // outward normal = tangent turned clockwise
            const Tensor<1, dim> t =
              reference[face_nodes[1]] - reference[face_nodes[0]];
            Tensor<1, dim> n;
            n[0] = t[1];
            n[1] = -t[0];
            if (n * (cell->face(f)->center() - cell->center()) < 0)
              std::swap(face_nodes[0], face_nodes[1]);
            for (const unsigned int node : face_nodes)
              node_faces[node].push_back(faces.size());
            faces.push_back(face_nodes);
            depth.push_back(cell->measure() / cell->face(f)->measure());
          }

    reference_weight.assign(reference.size(), 0.);
    for (const auto &face : faces)
      {
        const double length = reference[face[0]].distance(reference[face[1]]);
        reference_weight[face[0]] += length / 2;
        reference_weight[face[1]] += length / 2;
      }
    for (const auto &nf : node_faces)
      AssertThrow(nf.size() <= 2,
                  ExcMessage("A contact surface node belongs to more than two "
                             "faces: the surface must be a curve."));
  }

  template <int dim>
  unsigned int
  ContactSurface<dim>::neighbour(const unsigned int node,
                                 const unsigned int face) const
  {
    for (const unsigned int f : node_faces[node])
      if (f != face)
        return faces[f][0] == node ? faces[f][1] : faces[f][0];
    return invalid;
  }

  template class ContactSurface<2>;
  template class ContactSurface<3>;
} // namespace ContactDynamics

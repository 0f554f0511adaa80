#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/contact_parameters.h>
#include <contact_dynamics/contact/coordinates.h>
#include <contact_dynamics/contact/setup_caveats.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ContactDynamics
{
  namespace
  {
    /** The outward normal of a face (unit length), reference positions. */
    template <int dim>
    Tensor<1, dim>
    reference_normal(const ContactSurface<dim> &s, const unsigned int face)
    {
      const auto    &x = s.faces[face];
      Tensor<1, dim> n;
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> t = s.reference[x[1]] - s.reference[x[0]];
          n[0]                   = t[1];
          n[1]                   = -t[0];
        }
      else
        n = cross_product_3d(s.reference[x[1]] - s.reference[x[0]],
                             s.reference[x[2]] - s.reference[x[0]]);
      return n / n.norm();
    }
  } // namespace

  template <int dim>
  std::string
  complementarity_scale_caveat(
    const ContactParameters                        &contact,
    const std::vector<const ContactSurface<dim> *> &secondary_surfaces,
    const double                                    c_n,
    const bool                                      weighted_gap,
    const std::string                              &parameter)
  {
    const auto   stiffest = std::max_element(contact.youngs_moduli.begin(),
                                           contact.youngs_moduli.end());
    double       size     = 0;
    unsigned int n_faces  = 0;
    for (const ContactSurface<dim> *s : secondary_surfaces)
      for (unsigned int f = 0; f < s->n_faces(); ++f)
        {
          const auto &x = s->faces[f];
          // (the diagonal in 3-D: the edge of a square face times sqrt 2)
          size += s->reference[x[0]].distance(s->reference[x.back()]) /
                  std::sqrt(dim - 1.);
          ++n_faces;
        }
    if (stiffest == contact.youngs_moduli.end() || n_faces == 0)
      return "";
    size /= n_faces;
    const double stiffness = *stiffest / size;
    const double ratio =
      c_n * (weighted_gap ? std::pow(size, dim - 1) : 1.) / stiffness;
    std::ostringstream message;
    message << parameter << " = " << format_number(c_n) << " is "
            << format_number(ratio)
            << " times E/h = " << format_number(stiffness)
            << " (Young's modulus " << format_number(*stiffest)
            << " of the body '"
            << contact.body_names[stiffest - contact.youngs_moduli.begin()]
            << "' over the mean secondary face size " << format_number(size)
            << (weighted_gap ? "; the unnormalized weighted gap carries a "
                               "face measure h^(dim-1) more" :
                               "")
            << ")";
    AssertThrow(!(ratio > 1e10),
                ExcMessage(message.str() +
                           ": round-off in c_n times the gap would outweigh "
                           "every contact pressure. Allowed: up to 1e10 E/h; "
                           "the shipped examples use 1e-3 to 13 E/h."));
    if (ratio > 1e4)
      return message.str() +
             ": above about 1e4 E/h the semi-smooth Newton method stalls "
             "(3-D bouncing block: 12 step cuts at 2e5 E/h, none up to 2e3, "
             "no progress at 2e7). The shipped examples use 1e-3 to 13 E/h.";
    return "";
  }

  template <int dim>
  std::string
  secondary_corner_caveat(
    const ContactParameters                        &contact,
    const std::vector<const ContactSurface<dim> *> &secondary_surfaces)
  {
    // every face at every node, sorted by node: a node of two pairs'
    // surfaces has the same unknowns in both (nodes of two bodies at one
    // place do not)
    struct FaceAtNode
    {
      types::global_dof_index key; // the node's first unknown
      Point<dim>              where;
      Tensor<1, dim>          normal;
      unsigned int            pair;
    };
    std::vector<FaceAtNode> faces;
    for (unsigned int p = 0; p < secondary_surfaces.size(); ++p)
      if (contact.pairs[p].obstacle < 0)
        {
          const ContactSurface<dim> &s = *secondary_surfaces[p];
          for (unsigned int f = 0; f < s.n_faces(); ++f)
            {
              const Tensor<1, dim> n = reference_normal(s, f);
              for (const unsigned int j : s.faces[f])
                faces.push_back({s.dofs[j][0], s.reference[j], n, p});
            }
        }
    std::sort(faces.begin(), faces.end(), [](const auto &a, const auto &b) {
      return a.key < b.key;
    });
    double       sharpest = std::cos(M_PI / 3); // cos of the angle
    unsigned int n_nodes  = 0;
    std::array<unsigned int, 2> pairs{{0, 0}};
    Point<dim>                  where;
    for (std::size_t begin = 0, end = 0; begin < faces.size(); begin = end)
      {
        end = begin;
        while (end < faces.size() && faces[end].key == faces[begin].key)
          ++end;
        bool corner = false;
        for (std::size_t a = begin; a < end; ++a)
          for (std::size_t b = a + 1; b < end; ++b)
            {
              const double c = faces[a].normal * faces[b].normal;
              corner         = corner || c < std::cos(M_PI / 3);
              if (c < sharpest)
                {
                  sharpest = c;
                  pairs    = {{faces[a].pair, faces[b].pair}};
                  where    = faces[a].where;
                }
            }
        n_nodes += corner;
      }
    if (n_nodes == 0)
      return "";
    std::ostringstream message;
    const std::string &first = contact.pairs[pairs[0]].name;
    if (pairs[0] == pairs[1])
      message << "The secondary surface of the mortar pair '" << first
              << "' turns by ";
    else
      message << "The secondary surfaces of the mortar pairs '" << first
              << "' and '" << contact.pairs[pairs[1]].name << "' meet at ";
    message << format_number(
                 std::round(std::acos(std::max(sharpest, -1.)) * 180 / M_PI))
            << " degrees at the node " << coordinates(where) << " (" << n_nodes
            << " node(s) with faces more than 60 degrees apart). Dual mortar "
               "gives such a node one multiplier along the mean of its "
               "faces' normals, which fits neither face: once the corner "
               "touches, Newton does not converge (a block whose bottom and "
               "side are secondary stops at its first contact). Keep the "
               "secondary surface smooth: leave the corner's other side out "
               "of the pair, make the cornered surface the primary side, or "
               "use Contact/Formulation = node to segment.";
    return message.str();
  }

#define INSTANTIATE(dim)                              \
  template std::string complementarity_scale_caveat(  \
    const ContactParameters &,                        \
    const std::vector<const ContactSurface<dim> *> &, \
    const double,                                     \
    const bool,                                       \
    const std::string &);                             \
  template std::string secondary_corner_caveat(       \
    const ContactParameters &,                        \
    const std::vector<const ContactSurface<dim> *> &);
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics

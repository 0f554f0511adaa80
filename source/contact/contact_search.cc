#include <deal.II/numerics/rtree.h>

#include <contact_dynamics/contact/contact_search.h>

#include <algorithm>

namespace ContactDynamics
{
  template <int dim>
  std::vector<std::vector<unsigned int>>
  find_candidate_pairs(const std::vector<BoundingBox<dim>> &secondary,
                       const std::vector<BoundingBox<dim>> &primary)
  {
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> leaves;
    leaves.reserve(primary.size());
    for (unsigned int i = 0; i < primary.size(); ++i)
      leaves.emplace_back(primary[i], i);
    const auto tree = pack_rtree(leaves);

    std::vector<std::vector<unsigned int>> result(secondary.size());
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
    for (unsigned int s = 0; s < secondary.size(); ++s)
      {
        hits.clear();
        tree.query(boost::geometry::index::intersects(secondary[s]),
                   std::back_inserter(hits));
        for (const auto &h : hits)
          result[s].push_back(h.second);
        std::sort(result[s].begin(), result[s].end());
      }
    return result;
  }

  template std::vector<std::vector<unsigned int>>
  find_candidate_pairs<2>(const std::vector<BoundingBox<2>> &,
                          const std::vector<BoundingBox<2>> &);
  template std::vector<std::vector<unsigned int>>
  find_candidate_pairs<3>(const std::vector<BoundingBox<3>> &,
                          const std::vector<BoundingBox<3>> &);
} // namespace ContactDynamics

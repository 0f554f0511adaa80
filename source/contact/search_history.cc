#include <contact_dynamics/contact/search_history.h>
#include <contact_dynamics/output/checkpoint.h>

namespace ContactDynamics
{
  template <int dim>
  void
  SearchHistory<dim>::save(CheckpointData &data,
                           const ContactHistoryContext &) const
  {
    for (unsigned int p = 0; p < pairs.size(); ++p)
      save_per_process(comm,
                       data,
                       contact_pair_key(p) + "pattern",
                       pairs[p].pattern);
  }

  template <int dim>
  void
  SearchHistory<dim>::load(const CheckpointData        &data,
                           const ContactHistoryContext &context)
  {
    committed_u = *context.u;
    // the next search starts from this committed state
    committed_is_next = false;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        auto &pair = pairs[p];
        auto  pattern =
          (*context.node_maps)[p].empty() ?
             load_per_process(comm, data, contact_pair_key(p) + "pattern") :
             Pattern();
        if (pattern.size() == n_patches(pair))
          pair.pattern = std::move(pattern);
        else
          pair.pattern = new_pattern(pair, *context.u);
      }
  }

  template class SearchHistory<2>;
  template class SearchHistory<3>;
} // namespace ContactDynamics

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/output/checkpoint.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace ContactDynamics
{
  using namespace dealii;
  namespace fs = std::filesystem;

  namespace
  {
    // the first line of the file: a format version
    const std::string tag = "contact-dynamics checkpoint 1\n";

    template <typename T>
    void
    put(std::ostream &out, const T &x)
    {
      out.write(reinterpret_cast<const char *>(&x), sizeof(T));
    }

    template <typename T>
    T
    take(std::istream &in)
    {
      T x{};
      in.read(reinterpret_cast<char *>(&x), sizeof(T));
      return x;
    }

    void
    put_string(std::ostream &out, const std::string &s)
    {
      put<std::uint64_t>(out, s.size());
      out.write(s.data(), s.size());
    }

    std::string
    take_string(std::istream &in, const std::string &filename)
    {
      const auto size = take<std::uint64_t>(in);
      AssertThrow(in && size < (std::uint64_t(1) << 40),
                  ExcMessage("The checkpoint file '" + filename +
                             "' is damaged (a text of impossible length)."));
      std::string s(size, '\0');
      in.read(s.data(), size);
      return s;
    }

    bool
    is_checkpoint(const fs::path &path)
    {
      return fs::is_regular_file(path / Checkpoints::data_file);
    }
  } // namespace

  const std::vector<double> &
  CheckpointData::get(const std::string &name, const std::size_t size) const
  {
    const auto it = numbers.find(name);
    AssertThrow(it != numbers.end(),
                ExcMessage("The checkpoint '" + source + "' has no entry '" +
                           name +
                           "': it was written by a run with other "
                           "parameters (or another version)."));
    AssertThrow(size == 0 || it->second.size() == size,
                ExcMessage("The checkpoint '" + source + "' has " +
                           std::to_string(it->second.size()) +
                           " values of '" + name + "' where " +
                           std::to_string(size) +
                           " are expected: it was written by a run with "
                           "other parameters."));
    return it->second;
  }

  const std::string &
  CheckpointData::text(const std::string &name) const
  {
    const auto it = texts.find(name);
    AssertThrow(it != texts.end(),
                ExcMessage("The checkpoint '" + source + "' has no entry '" +
                           name + "'."));
    return it->second;
  }

  void
  CheckpointData::write(const std::string &filename) const
  {
    errno = 0;
    std::ofstream out(filename, std::ios::binary);
    out << tag;
    put<std::uint64_t>(out, numbers.size());
    for (const auto &[name, values] : numbers)
      {
        put_string(out, name);
        put<std::uint64_t>(out, values.size());
        out.write(reinterpret_cast<const char *>(values.data()),
                  values.size() * sizeof(double));
      }
    put<std::uint64_t>(out, texts.size());
    for (const auto &[name, text] : texts)
      {
        put_string(out, name);
        put_string(out, text);
      }
    out.close();
    AssertThrow(out,
                ExcMessage("Cannot write the checkpoint file '" + filename +
                           "': " + std::strerror(errno) + "."));
  }

  void
  CheckpointData::read(const std::string &filename)
  {
    numbers.clear();
    texts.clear();
    source = fs::path(filename).parent_path().string();
    errno  = 0;
    std::ifstream in(filename, std::ios::binary);
    AssertThrow(in,
                ExcMessage("Cannot read the checkpoint file '" + filename +
                           "': " + std::strerror(errno) + "."));
    std::string first(tag.size(), '\0');
    in.read(first.data(), first.size());
    AssertThrow(in && first == tag,
                ExcMessage("The file '" + filename +
                           "' is not a checkpoint of this program."));
    const auto n_numbers = take<std::uint64_t>(in);
    for (std::uint64_t i = 0; in && i < n_numbers; ++i)
      {
        const std::string name = take_string(in, filename);
        const auto        size = take<std::uint64_t>(in);
        AssertThrow(in && size < (std::uint64_t(1) << 40),
                    ExcMessage("The checkpoint file '" + filename +
                               "' is damaged (entry '" + name + "')."));
        std::vector<double> values(size);
        in.read(reinterpret_cast<char *>(values.data()),
                size * sizeof(double));
        numbers[name] = std::move(values);
      }
    const auto n_texts = take<std::uint64_t>(in);
    for (std::uint64_t i = 0; in && i < n_texts; ++i)
      {
        const std::string name = take_string(in, filename);
        texts[name]            = take_string(in, filename);
      }
    AssertThrow(in,
                ExcMessage("The checkpoint file '" + filename +
                           "' is truncated or damaged."));
  }

  namespace Checkpoints
  {
    std::string
    directory(const std::string &output_directory, const unsigned int step)
    {
      return output_directory + "/checkpoints/step-" +
             Utilities::int_to_string(step, 7);
    }

    void
    create_temporary(const std::string &temporary)
    {
      std::error_code error;
      fs::remove_all(temporary, error);
      fs::create_directories(temporary, error);
      AssertThrow(!error && fs::is_directory(temporary),
                  ExcMessage("Cannot create the checkpoint directory '" +
                             temporary + "': " + error.message() + "."));
    }

    void
    commit(const std::string &temporary,
           const std::string &final,
           const unsigned int keep)
    {
      std::error_code error;
      // a checkpoint of the same step (a restarted run passing it again)
      fs::remove_all(final, error);
      fs::rename(temporary, final, error);
      AssertThrow(!error,
                  ExcMessage("Cannot rename the checkpoint directory '" +
                             temporary + "' to '" + final +
                             "': " + error.message() + "."));
      // the names sort as the steps do
      std::vector<fs::path> complete;
      for (const auto &entry : fs::directory_iterator(
             fs::path(final).parent_path()))
        {
          const std::string name = entry.path().filename().string();
          if (name.rfind("step-", 0) != 0)
            continue;
          if (entry.path().extension() == ".part")
            fs::remove_all(entry.path(), error);
          else
            complete.push_back(entry.path());
        }
      std::sort(complete.begin(), complete.end());
      // those of later steps continue an abandoned run (this one restarted
      // from an earlier checkpoint, and its files no longer reach them)
      while (!complete.empty() && complete.back() > fs::path(final))
        {
          fs::remove_all(complete.back(), error);
          complete.pop_back();
        }
      for (std::size_t i = 0; i + keep < complete.size(); ++i)
        fs::remove_all(complete[i], error);
    }

    std::string
    find(const std::string &path)
    {
      AssertThrow(fs::exists(path),
                  ExcMessage("--restart " + path +
                             ": no such file or directory."));
      if (is_checkpoint(path))
        return path;
      std::vector<fs::path> complete;
      const fs::path        under = fs::path(path) / "checkpoints";
      if (fs::is_directory(under))
        for (const auto &entry : fs::directory_iterator(under))
          if (entry.path().extension() != ".part" &&
              is_checkpoint(entry.path()))
            complete.push_back(entry.path());
      AssertThrow(!complete.empty(),
                  ExcMessage("--restart " + path +
                             ": neither a checkpoint (a directory with " +
                             data_file +
                             ") nor an output directory with a complete "
                             "checkpoint in its checkpoints/ directory."));
      return std::max_element(complete.begin(), complete.end())->string();
    }
  } // namespace Checkpoints
} // namespace ContactDynamics

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/output/checkpoint.h>

#include <algorithm>
#include <boost/crc.hpp>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

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

    // (with either file: a checkpoint missing one is damaged, not absent)
    bool
    is_checkpoint(const fs::path &path)
    {
      return path.extension() != ".part" &&
             (fs::is_regular_file(path / Checkpoints::data_file) ||
              fs::is_regular_file(path / Checkpoints::checksum_file));
    }

    // every file in `path` has a name this program gives the files of a
    // checkpoint (those of p4est, write_file_atomically's temporary): the
    // only directories it removes or replaces
    bool
    holds_only_checkpoint_files(const fs::path &path)
    {
      const std::set<std::string> names = {
        Checkpoints::data_file,
        Checkpoints::parameter_file,
        std::string(Checkpoints::parameter_file) + ".part",
        Checkpoints::checksum_file,
        std::string(Checkpoints::checksum_file) + ".part",
        "mesh",
        "mesh.info",
        "mesh_fixed.data",
        "mesh_variable.data"};
      std::error_code error;
      if (!fs::is_directory(path, error))
        return false;
      for (const auto &entry : fs::directory_iterator(path, error))
        if (!entry.is_regular_file() ||
            names.count(entry.path().filename().string()) == 0)
          return false;
      return !error;
    }

    // the size and CRC-32 of a file; `readable` false if it could not be
    // read to its end
    std::pair<std::uintmax_t, std::uint32_t>
    size_and_checksum(const fs::path &file, bool &readable)
    {
      std::ifstream      in(file, std::ios::binary);
      boost::crc_32_type crc;
      std::vector<char>  buffer(1 << 20);
      std::uintmax_t     size = 0;
      while (in)
        {
          in.read(buffer.data(), buffer.size());
          crc.process_bytes(buffer.data(), in.gcount());
          size += in.gcount();
        }
      readable = in.eof() && !in.bad();
      return {size, crc.checksum()};
    }

    // the step of a checkpoint directory step-N (names sort as text only
    // up to 7 digits)
    bool
    is_step_name(const fs::path &path)
    {
      return path.filename().string().rfind("step-", 0) == 0;
    }

    unsigned long long
    step_of(const fs::path &path)
    {
      const std::string name = path.filename().string();
      return is_step_name(path) ? std::strtoull(name.c_str() + 5, nullptr, 10) :
                                  0;
    }

    // a checkpoint this program wrote, complete or damaged: not empty, and
    // nothing in it but the names of its files
    bool
    is_own(const fs::path &path)
    {
      std::error_code error;
      return holds_only_checkpoint_files(path) && !fs::is_empty(path, error) &&
             !error;
    }

    void
    sort_by_step(std::vector<fs::path> &paths)
    {
      std::sort(paths.begin(), paths.end(), [](const auto &a, const auto &b) {
        return step_of(a) < step_of(b);
      });
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
                           std::to_string(it->second.size()) + " values of '" +
                           name + "' where " + std::to_string(size) +
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
        in.read(reinterpret_cast<char *>(values.data()), size * sizeof(double));
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
    create_temporary(const std::string &temporary, const std::string &final)
    {
      // a directory of the user's under either name is left alone
      for (const std::string &name : {temporary, final})
        AssertThrow(!fs::exists(name) ||
                      (name == temporary ? holds_only_checkpoint_files(name) :
                                           is_own(name)),
                    ExcMessage(
                      "The checkpoint cannot be written to '" + final + "': '" +
                      name +
                      "' exists and holds files this program did not write "
                      "there. Move it away (nothing in it was changed)."));
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
      // a checkpoint of the same step (a restarted run passing it again):
      // out of the way first under a name find() ignores
      const std::string old = final + ".old.part";
      if (fs::exists(final))
        {
          fs::remove_all(old, error);
          fs::rename(final, old, error);
          AssertThrow(!error,
                      ExcMessage("Cannot move the checkpoint directory '" +
                                 final + "' aside to '" + old +
                                 "': " + error.message() + "."));
        }
      fs::rename(temporary, final, error);
      if (error)
        {
          std::error_code back;
          if (fs::exists(old))
            fs::rename(old, final, back);
          AssertThrow(false,
                      ExcMessage("Cannot rename the checkpoint directory '" +
                                 temporary + "' to '" + final +
                                 "': " + error.message() + "."));
        }
      // the names sort as the steps do
      std::vector<fs::path> complete;
      for (const auto &entry :
           fs::directory_iterator(fs::path(final).parent_path()))
        {
          if (!is_step_name(entry.path()))
            continue;
          if (entry.path().extension() == ".part")
            {
              if (holds_only_checkpoint_files(entry.path()))
                fs::remove_all(entry.path(), error);
            }
          else if (is_own(entry.path()))
            complete.push_back(entry.path());
        }
      sort_by_step(complete);
      // those of later steps continue an abandoned run (this one restarted
      // from an earlier checkpoint, and its files no longer reach them)
      while (!complete.empty() &&
             step_of(complete.back()) > step_of(fs::path(final)))
        {
          fs::remove_all(complete.back(), error);
          complete.pop_back();
        }
      for (std::size_t i = 0; i + keep < complete.size(); ++i)
        fs::remove_all(complete[i], error);
    }

    void
    write_checksums(const std::string &directory)
    {
      std::ostringstream list;
      unsigned int       n_files = 0;
      for (const auto &entry : fs::directory_iterator(directory))
        {
          const std::string name = entry.path().filename().string();
          if (name == checksum_file || !entry.is_regular_file())
            continue;
          bool       readable = false;
          const auto sum      = size_and_checksum(entry.path(), readable);
          AssertThrow(readable,
                      ExcMessage("Cannot read back the checkpoint file '" +
                                 entry.path().string() + "'."));
          list << sum.first << ' ' << sum.second << ' ' << name << '\n';
          ++n_files;
        }
      const std::string file = directory + "/" + checksum_file;
      errno                  = 0;
      std::ofstream out(file);
      // the last line counts the others: a list cut at a line is damaged
      out << list.str() << "files " << n_files << '\n';
      out.close();
      AssertThrow(out,
                  ExcMessage("Cannot write the checkpoint file '" + file +
                             "': " + std::strerror(errno) + "."));
    }

    void
    verify(const std::string &checkpoint, const std::string &only)
    {
      const std::string list_file = checkpoint + "/" + checksum_file;
      std::ifstream     in(list_file);
      AssertThrow(in,
                  ExcMessage("The checkpoint '" + checkpoint +
                             "' cannot be verified: it has no readable "
                             "list of checksums '" +
                             checksum_file +
                             "' (its writing did not complete, the file "
                             "was removed, or a version of this program "
                             "before checksums wrote it). Restart from "
                             "another checkpoint."));
      const auto damaged = [&](const std::string &file,
                               const std::string &what) {
        return ExcMessage("The checkpoint '" + checkpoint +
                          "' is damaged: its file '" + file + "' " + what +
                          ". Nothing was read or changed; restart from "
                          "another checkpoint (the one before it is kept "
                          "next to it).");
      };
      std::string           line;
      std::set<std::string> listed;
      bool                  counted = false;
      while (std::getline(in, line))
        {
          AssertThrow(!counted,
                      damaged(checksum_file, "has lines after its count"));
          if (line.rfind("files ", 0) == 0)
            {
              AssertThrow(line == "files " + std::to_string(listed.size()),
                          damaged(checksum_file,
                                  "lists " + std::to_string(listed.size()) +
                                    " files where its last line says '" +
                                    line.substr(0, 40) + "'"));
              counted = true;
              continue;
            }
          std::istringstream fields(line);
          std::uintmax_t     size = 0;
          std::uint32_t      sum  = 0;
          std::string        name;
          AssertThrow((fields >> size >> sum) && std::getline(fields, name) &&
                        name.size() > 1 && name[0] == ' ' &&
                        name.find('/') == std::string::npos,
                      damaged(checksum_file,
                              "has a line that is not 'size "
                              "checksum name': '" +
                                line.substr(0, 80) + "'"));
          name = name.substr(1);
          listed.insert(name);
          if (!only.empty() && name != only)
            continue;
          const fs::path file = fs::path(checkpoint) / name;
          AssertThrow(fs::is_regular_file(file), damaged(name, "is missing"));
          bool       readable = false;
          const auto found    = size_and_checksum(file, readable);
          AssertThrow(readable, damaged(name, "cannot be read"));
          AssertThrow(found.first == size,
                      damaged(name,
                              "has " + std::to_string(found.first) +
                                " bytes where " + std::to_string(size) +
                                " were written (truncated or extended)"));
          AssertThrow(found.second == sum,
                      damaged(name,
                              "does not have the checksum it was written "
                              "with (its content changed)"));
        }
      AssertThrow(counted,
                  damaged(checksum_file,
                          "is incomplete (no count of the files at its end)"));
      const std::string needed = only.empty() ? data_file : only;
      AssertThrow(listed.count(needed) > 0,
                  damaged(checksum_file,
                          "does not list '" + needed +
                            "' (the list is damaged)"));
    }

    void
    check_free_space(const std::string &directory, const double bytes)
    {
      std::error_code error;
      double          available = fs::space(directory, error).available;
      // for the test of a full disk (tests/CMakeLists.txt)
      if (const char *free = std::getenv("CONTACT_DYNAMICS_FREE_BYTES"))
        available = std::atof(free);
      AssertThrow(error || available >= bytes,
                  ExcMessage("Not enough free space for the checkpoint in '" +
                             directory + "': " +
                             std::to_string(std::llround(available / 1e6)) +
                             " MB free, about " +
                             std::to_string(std::llround(bytes / 1e6 + 0.5)) +
                             " MB needed. Free space, or raise Output/"
                             "Checkpoint interval (the outputs so far are "
                             "complete; restart from the last checkpoint)."));
    }

    namespace
    {
      std::map<std::string, std::string>
      entries(const std::string &text)
      {
        std::map<std::string, std::string> values;
        std::vector<std::string>           path;
        std::istringstream                 in(text);
        std::string                        line;
        while (std::getline(in, line))
          {
            line = Utilities::trim(line);
            if (line.rfind("subsection ", 0) == 0)
              path.push_back(Utilities::trim(line.substr(11)));
            else if (line == "end" && !path.empty())
              path.pop_back();
            else if (line.rfind("set ", 0) == 0 &&
                     line.find('=') != std::string::npos)
              {
                std::string name;
                for (const auto &p : path)
                  name += p + "/";
                name += Utilities::trim(line.substr(4, line.find('=') - 4));
                values[name] = Utilities::trim(line.substr(line.find('=') + 1));
              }
          }
        return values;
      }
    } // namespace

    // entries added after checkpoints were first written, with the value
    // that older runs had
    const std::map<std::string, std::string> entries_added_later = {
      {"Finite element/Polynomial degree", "1"}};

    std::vector<std::string>
    changed_entries(const std::string              &old_text,
                    const std::string              &new_text,
                    const std::vector<std::string> &allowed)
    {
      const auto old_values = entries(old_text), new_values = entries(new_text);
      std::set<std::string> names;
      for (const auto &[name, value] : old_values)
        names.insert(name);
      for (const auto &[name, value] : new_values)
        names.insert(name);
      std::vector<std::string> changed;
      for (const auto &name : names)
        {
          // "A/": every entry of A; "/b": the entry b of any subsection
          if (std::any_of(allowed.begin(), allowed.end(), [&](const auto &a) {
                return a.front() == '/' ?
                         name.size() >= a.size() &&
                           name.compare(name.size() - a.size(), a.size(), a) ==
                             0 :
                         name.rfind(a, 0) == 0;
              }))
            continue;
          const auto o = old_values.find(name), n = new_values.find(name);
          // a checkpoint older than an entry ran with the entry's default
          const auto        added  = entries_added_later.find(name);
          const std::string before = o != old_values.end() ? o->second :
                                     added != entries_added_later.end() ?
                                                             added->second :
                                                             "(none)";
          const std::string after =
            n == new_values.end() ? "(none)" : n->second;
          if (before != after)
            changed.push_back(name + ": " + before + " -> " + after);
        }
      return changed;
    }

    std::string
    tail_hash(const std::string &file, const std::uintmax_t size)
    {
      std::ifstream in(file, std::ios::binary);
      if (!in)
        return "";
      const std::uintmax_t length = std::min<std::uintmax_t>(size, 4096);
      in.seekg(size - length);
      std::string bytes(length, '\0');
      in.read(bytes.data(), length);
      if (!in)
        return "";
      // FNV-1a, 64 bits
      std::uint64_t hash = 1469598103934665603ull;
      for (const unsigned char c : bytes)
        hash = (hash ^ c) * 1099511628211ull;
      std::ostringstream text;
      text << std::hex << hash << ":" << std::dec << size;
      return text.str();
    }

    void
    remove_later(const std::string &checkpoint)
    {
      const fs::path  path(checkpoint);
      std::error_code error;
      for (const auto &entry :
           fs::directory_iterator(path.parent_path(), error))
        if (is_step_name(entry.path()) && entry.path().extension() != ".part" &&
            step_of(entry.path()) > step_of(path) && is_own(entry.path()))
          fs::remove_all(entry.path(), error);
    }

    void
    remove_all_checkpoints(const std::string &output_directory)
    {
      const fs::path  directory = fs::path(output_directory) / "checkpoints";
      std::error_code error;
      if (!fs::is_directory(directory, error))
        return;
      for (const auto &entry : fs::directory_iterator(directory, error))
        if (is_step_name(entry.path()) &&
            (is_own(entry.path()) ||
             (entry.path().extension() == ".part" &&
              holds_only_checkpoint_files(entry.path()))))
          fs::remove_all(entry.path(), error);
      // only if nothing else is in it
      fs::remove(directory, error);
    }

    std::string
    find(const std::string &given)
    {
      AssertThrow(fs::exists(given),
                  ExcMessage("--restart " + given +
                             ": no such file or directory."));
      // 'out/', '.', relative to anywhere: one absolute name
      fs::path path = fs::absolute(given).lexically_normal();
      if (!path.has_filename())
        path = path.parent_path();
      AssertThrow(path.extension() != ".part" || !is_step_name(path),
                  ExcMessage("--restart " + given +
                             ": a checkpoint that was not completed (its "
                             "writing was interrupted); give the output "
                             "directory to take the newest complete one."));
      if (is_checkpoint(path))
        return path.string();
      std::vector<fs::path> complete;
      for (const fs::path &under : {path / "checkpoints", path})
        if (complete.empty() && fs::is_directory(under))
          for (const auto &entry : fs::directory_iterator(under))
            if (is_step_name(entry.path()) && is_checkpoint(entry.path()))
              complete.push_back(entry.path());
      AssertThrow(!complete.empty(),
                  ExcMessage("--restart " + given +
                             ": neither a checkpoint (a directory with " +
                             data_file +
                             ") nor an output directory with a complete "
                             "checkpoint in its checkpoints/ directory."));
      sort_by_step(complete);
      return complete.back().string();
    }
  } // namespace Checkpoints
} // namespace ContactDynamics

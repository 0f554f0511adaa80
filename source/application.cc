#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <contact_dynamics/application.h>
#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/output/postprocessing.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/scenes/scene_registry.h>
#include <contact_dynamics/simulator.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

namespace ContactDynamics
{
  namespace
  {
    void
    declare_dimension(ParameterHandler &prm)
    {
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "Space dimension: 2 (plane strain) or 3. The "
                        "scenes in 3-D: " +
                          scene_names(3, ", ") + ".");
    }

    template <int dim>
    SceneLayout
    layout_from(ParameterHandler &prm)
    {
      Scene<dim> scene;
      scene.parse_parameters(prm);
      SceneLayout layout    = scene.layout();
      layout.obstacle_names = obstacle_names(prm);
      return layout;
    }

    template <int dim>
    void
    run(ParameterHandler  &prm,
        const std::string &filename,
        std::ostream      &screen,
        const bool         validate_only,
        const std::string &checkpoint)
    {
      const MPI_Comm comm = MPI_COMM_WORLD;
      // a run that stops destroys the simulator before the error leaves
      // here: its TimerOutput then has nothing to say about an uncaught
      // exception
      std::exception_ptr failure;
      {
        std::unique_ptr<Simulator<dim>> simulator;
        // from the start of the setup: a signal during it stops the run at
        // step 0 with its checkpoint (doc/restart.md), not silently
        if (!validate_only)
          install_stop_handlers();
        check_collectively(comm, [&]() {
          simulator = std::make_unique<Simulator<dim>>(prm, screen, comm);
        });
        if (validate_only)
          {
            if (is_root(comm))
              screen << filename << ": the parameters are valid." << std::endl;
            return;
          }
        try
          {
            prm.enter_subsection("Output");
            const std::string directory = prm.get("Output directory");
            prm.leave_subsection();
            // the first process writes; every process learns if it failed
            // (a restart writes it once it has checked the parameters)
            check_collectively(comm, [&]() {
              if (is_root(comm) && checkpoint.empty())
                {
                  create_output_directory(directory);
                  write_file_atomically(
                    directory + "/parameters.prm",
                    [&](std::ostream &out) {
                      prm.print_parameters(out, ParameterHandler::ShortPRM);
                    });
                }
            });
            simulator->run(checkpoint);
          }
        catch (...)
          {
            failure = std::current_exception();
          }
      }
      if (failure)
        std::rethrow_exception(failure);
    }

    /**
     * What ParameterHandler would silently accept: a file that sets nothing
     * (the defaults would run), and an entry set twice in one subsection
     * (the last value would win). Follows `subsection`/`end` and
     * `include`, as ParameterHandler does.
     */
    class EntryScan
    {
    public:
      void
      scan(const std::string        &filename,
           std::vector<std::string> &path,
           const std::string        &included_from = "")
      {
        const std::string from =
          included_from.empty() ? "" : " (included from " + included_from + ")";
        AssertThrow(!std::filesystem::is_directory(filename),
                    ExcMessage("The parameter file '" + filename + "'" + from +
                               " is a directory."));
        std::ifstream in(filename);
        AssertThrow(in,
                    ExcMessage("Cannot open the parameter file '" + filename +
                               "'" + from + ": " + std::strerror(errno) + "."));
        // an include cycle would recurse without end
        const std::string canonical =
          std::filesystem::weakly_canonical(filename).string();
        AssertThrow(std::find(open.begin(), open.end(), canonical) ==
                      open.end(),
                    ExcMessage("The parameter file '" + filename + "'" + from +
                               " is already being read: an include cycle."));
        open.push_back(canonical);
        std::string  line, text;
        unsigned int number = 0, first = 0;
        while (std::getline(in, line))
          {
            ++number;
            if (text.empty())
              first = number;
            line = line.substr(0, line.find('#'));
            // a backslash at the end continues the line
            const std::string trimmed = Utilities::trim(line);
            if (!trimmed.empty() && trimmed.back() == '\\')
              {
                text += trimmed.substr(0, trimmed.size() - 1) + " ";
                continue;
              }
            text += line;
            statement(Utilities::trim(text), filename, first, path);
            text.clear();
          }
        open.pop_back();
      }

      unsigned int n_set = 0;

    private:
      static bool
      keyword(const std::string &text, const std::string &word)
      {
        if (text.size() < word.size())
          return false;
        for (std::size_t i = 0; i < word.size(); ++i)
          if (std::tolower(text[i]) != word[i])
            return false;
        return text.size() == word.size() || text[word.size()] == ' ' ||
               text[word.size()] == '\t';
      }

      void
      statement(std::string               text,
                const std::string        &filename,
                const unsigned int        number,
                std::vector<std::string> &path)
      {
        for (auto &c : text)
          if (c == '\t')
            c = ' ';
        while (text.find("  ") != std::string::npos)
          text.erase(text.find("  "), 1);
        const std::string where =
          "line " + std::to_string(number) + " of " + filename;
        if (keyword(text, "subsection"))
          path.push_back(Utilities::trim(text.substr(10)));
        else if (keyword(text, "end"))
          {
            if (!path.empty())
              path.pop_back();
          }
        else if (keyword(text, "include"))
          scan(Utilities::trim(text.substr(7)), path, where);
        else if (keyword(text, "set") && text.find('=') != std::string::npos)
          {
            ++n_set;
            std::string name;
            for (const auto &p : path)
              name += p + "/";
            name += Utilities::trim(text.substr(3, text.find('=') - 3));
            // a file may override what a file it included set (a base
            // file and its variant); anything else set twice is a mistake
            const auto previous = seen.find(name);
            AssertThrow(previous == seen.end() ||
                          previous->second.second > open.size(),
                        ExcMessage("The entry '" + name + "' is set twice: " +
                                   previous->second.first + " and " + where +
                                   ". Set it once (the last value would "
                                   "silently win; a file may override only "
                                   "what a file it includes sets)."));
            seen[name] = {where, open.size()};
          }
      }

      // entry -> (where it was set, include depth of that file)
      std::map<std::string, std::pair<std::string, std::size_t>> seen;
      std::vector<std::string>                                   open;
    };
  } // namespace

  unsigned int
  read_parameters(const std::string &filename, ParameterHandler &prm)
  {
    {
      EntryScan                entries;
      std::vector<std::string> path;
      entries.scan(filename, path);
      AssertThrow(entries.n_set > 0,
                  ExcMessage("The parameter file '" + filename +
                             "' sets nothing (no 'set' line): it would run "
                             "the default scene with every default. Set at "
                             "least the scene (subsection Scene, set Scene = "
                             "...); 'contact-dynamics --print-parameters' "
                             "lists every parameter."));
    }
    // First pass: only the dimension and the scene, to learn the bodies.
    ParameterHandler first;
    declare_dimension(first);
    Scene<2>::declare_parameters(first);
    declare_obstacle_names(first);
    first.parse_input(filename, "", true);
    const unsigned int dim = first.get_integer("Dimension");
    const SceneLayout  layout =
      (dim == 2 ? layout_from<2>(first) : layout_from<3>(first));

    declare_dimension(prm);
    if (dim == 2)
      Simulator<2>::declare_parameters(prm, layout);
    else
      Simulator<3>::declare_parameters(prm, layout);
    prm.parse_input(filename);
    return dim;
  }

  void
  run_parameter_file(const std::string &filename,
                     std::ostream      &screen,
                     const bool         validate_only,
                     const std::string &restart)
  {
    // a restart finds its checkpoint, and its parameters unless given
    std::string checkpoint, parameters = filename;
    if (!restart.empty())
      check_collectively(MPI_COMM_WORLD, [&]() {
        checkpoint = Checkpoints::find(restart);
        if (parameters.empty())
          {
            parameters = checkpoint + "/" + Checkpoints::parameter_file;
            // (the rest is verified before the simulator reads it)
            if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
              Checkpoints::verify(checkpoint, Checkpoints::parameter_file);
          }
      });
    ParameterHandler prm;
    unsigned int     dim = 2;
    // every process reads the file: an error is raised on all of them
    check_collectively(MPI_COMM_WORLD, [&]() {
      dim = read_parameters(parameters, prm);
      // the run's own parameters continue where the checkpoint is, not
      // where its output directory was relative to
      const std::filesystem::path where(checkpoint); // absolute, normal
      if (!checkpoint.empty() && filename.empty() &&
          where.parent_path().filename() == "checkpoints")
        {
          prm.enter_subsection("Output");
          prm.set("Output directory",
                  where.parent_path().parent_path().string());
          prm.leave_subsection();
        }
    });
    if (dim == 2)
      run<2>(prm, parameters, screen, validate_only, checkpoint);
    else
      run<3>(prm, parameters, screen, validate_only, checkpoint);
  }

  namespace
  {
    void
    print_usage(std::ostream &out)
    {
      out << "Usage:\n"
          << "  contact-dynamics FILE.prm                run a simulation\n"
          << "  contact-dynamics --validate FILE.prm     check a parameter "
             "file without running it\n"
          << "  contact-dynamics --restart DIR [FILE.prm]\n"
          << "                                           continue from the "
             "newest checkpoint in DIR\n"
          << "                                           (an output "
             "directory or a checkpoint), with\n"
          << "                                           its parameters (or "
             "FILE.prm: a later End time)\n"
          << "  contact-dynamics --print-parameters [FILE.prm]\n"
          << "                                           print every "
             "parameter, documented, with\n"
          << "                                           the defaults (or "
             "the values of FILE.prm)\n"
          << "  contact-dynamics --help\n";
    }

    void
    print_parameters(const std::string &filename, std::ostream &out)
    {
      ParameterHandler prm;
      if (!filename.empty())
        check_collectively(MPI_COMM_WORLD, [&]() {
          read_parameters(filename, prm);
        });
      else
        {
          ParameterHandler first;
          declare_dimension(first);
          Scene<2>::declare_parameters(first);
          declare_obstacle_names(first);
          declare_dimension(prm);
          Simulator<2>::declare_parameters(prm, layout_from<2>(first));
        }
      prm.print_parameters(out, ParameterHandler::PRM);
    }

    /**
     * The threads per process: 1 unless DEAL_II_THREADS_PER_PROCESS asks
     * for more. False (with a message) if its value is not allowed.
     */
    bool
    threads_per_process(unsigned int &n_threads)
    {
      const char *threads = std::getenv("DEAL_II_THREADS_PER_PROCESS");
      n_threads           = 1;
      if (threads != nullptr)
        {
          char      *end   = nullptr;
          const long value = std::strtol(threads, &end, 10);
          if (end == threads || *end != '\0' || value < 1 || value > 1024)
            {
              std::cerr << "Error: the environment variable "
                           "DEAL_II_THREADS_PER_PROCESS is '"
                        << threads
                        << "': it must be a whole number of threads per "
                           "process in [1, 1024]."
                        << std::endl;
              return false;
            }
          n_threads = value;
        }
      return true;
    }

    /** What the command line `args` asks for, done; the exit status. */
    int
    run_arguments(const std::vector<std::string> &args, const bool root)
    {
      // the command line is the same on every process: its errors are
      // collective
      const auto one_file = [&](const std::size_t  first,
                                const std::string &what) {
        std::string files;
        for (std::size_t i = first; i < args.size(); ++i)
          files += " " + args[i];
        AssertThrow(args.size() == first + 1 && args[first].rfind("--", 0) != 0,
                    ExcCollective(what + "one parameter file expected, got " +
                                  std::to_string(args.size() - first) +
                                  (files.empty() ? "" : ":" + files) +
                                  ". Run 'contact-dynamics --help'."));
      };
      if (args.empty() || args[0] == "--help" || args[0] == "-h")
        {
          if (root)
            print_usage(std::cout);
          return args.empty() ? 1 : 0;
        }
      if (args[0] == "--print-parameters")
        {
          if (args.size() > 1)
            one_file(1, "--print-parameters: ");
          std::ostringstream text;
          print_parameters(args.size() == 2 ? args[1] : "", text);
          if (root)
            std::cout << text.str() << std::flush;
          return 0;
        }
      if (args[0] == "--validate")
        {
          one_file(1, "--validate: ");
          run_parameter_file(args[1], std::cout, true);
          return 0;
        }
      if (args[0] == "--restart")
        {
          AssertThrow(args.size() == 2 || args.size() == 3,
                      ExcCollective(
                        "--restart: a directory and at most one parameter "
                        "file expected. Run 'contact-dynamics --help'."));
          run_parameter_file(args.size() == 3 ? args[2] : "",
                             std::cout,
                             false,
                             args[1]);
          return 0;
        }
      AssertThrow(args[0].rfind("--", 0) != 0,
                  ExcCollective("Unknown option '" + args[0] +
                                "'. Run 'contact-dynamics --help'."));
      one_file(0, "");
      run_parameter_file(args[0], std::cout, false);
      return 0;
    }
  } // namespace

  int
  run_command_line(int argc, char **argv)
  {
    // One thread per process unless DEAL_II_THREADS_PER_PROCESS asks for
    // more: on this 2-core machine a second thread made the bouncing block
    // 7.7 s instead of 5.0 s (TBB's idle workers take the core from the
    // solver) and the ironing no faster (the bulk assembly's scatter into
    // the Epetra matrix is serial); doc/parallel.md.
    // a signal from here on stops a run at step 0 with its checkpoint
    // (doc/restart.md); --validate, --help and --print-parameters keep the
    // default action
    if (argc >= 2 && (std::string(argv[1]) == "--restart" ||
                      std::string(argv[1]).rfind("--", 0) != 0))
      install_stop_handlers();
    unsigned int n_threads = 1;
    if (!threads_per_process(n_threads))
      return 1;
    // started without mpirun, Open MPI would spawn a daemon for the one
    // process (0.2 s of every run, measured): a run on its own needs none
    if (std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr)
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, n_threads);
    const bool root = (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    try
      {
        const std::vector<std::string> args(argv + 1, argv + argc);
        return run_arguments(args, root);
      }
    catch (const ExcStopped &e)
      {
        if (root)
          std::cerr << "\n" << exception_message(e) << std::endl;
        MPI_Barrier(MPI_COMM_WORLD);
        return 128 + e.signal;
      }
    catch (const ExcCollective &e)
      {
        // raised on every process: printed once
        if (root)
          std::cerr << "\nError: " << exception_message(e) << std::endl;
        // mpirun kills the other processes as soon as one exits with an
        // error: none leaves before the message is out
        MPI_Barrier(MPI_COMM_WORLD);
        return 1;
      }
    catch (const std::exception &e)
      {
        if (n_processes == 1)
          {
            std::cerr << "\nError: " << exception_message(e) << std::endl;
            return 1;
          }
        // perhaps raised on this process only: the others may wait in a
        // collective operation forever, so end them all
        std::cerr << "\nError (on process "
                  << Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) << " of "
                  << n_processes << "): " << exception_message(e) << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
    return 1;
  }
} // namespace ContactDynamics

// the thin main opens the library and calls this (source/main.cc)
extern "C" int
contact_dynamics_run_command_line(int argc, char **argv)
{
  return ContactDynamics::run_command_line(argc, argv);
}

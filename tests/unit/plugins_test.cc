// SPDX-License-Identifier: LGPL-2.1-or-later
// The plugin families: registration from outside the library (this file), the
// choices a parameter file offers, nearest-name suggestions, and the
// Simulator's public API with a postprocessor and a driver of the program's
// own.
#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/fracture/criterion.h>
#include <pdfem/io/parameters.h>
#include <pdfem/simulator/postprocess.h>
#include <pdfem/simulator/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_vector.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <gtest/gtest.h>

namespace
{
  using namespace pdfem;
  namespace fs = std::filesystem;

  /// A driver of this program: the static driver's single step, counted.
  class CountingDriver : public Drivers::Interface
  {
  public:
    void
    run(Drivers::Host &host) override
    {
      Drivers::StaticDriver driver(parameters);
      driver.run(host.system(),
                 host.solution(),
                 [&host](const Drivers::StepRecord &record) {
                   host.after_equilibrium(record, false);
                 });
      ++runs;
    }
    std::map<std::string, double>
    timings() const override
    {
      return {};
    }
    static inline unsigned int runs = 0;
  };
  PDFEM_REGISTER_DRIVER(CountingDriver,
                        "test counting",
                        "a test driver registered by the unit tests")

  /// A postprocessor of this program: the largest x displacement, as a
  /// history column and a member of summary.json's "final".
  template <int dim>
  class LargestDisplacement : public Postprocess::Interface<dim>
  {
  public:
    std::vector<std::string>
    history_columns() override
    {
      return {"test_u_max"};
    }
    void
    history_values(std::vector<double> &row) override
    {
      row.push_back(this->get_solution().linfty_norm());
    }
    void
    write_final(IO::JsonWriter &json) const override
    {
      json.value("test_u_max", this->get_solution().linfty_norm());
    }
  };
  PDFEM_REGISTER_POSTPROCESSOR(LargestDisplacement,
                               "test largest displacement",
                               "a test postprocessor registered by the unit "
                               "tests")

  std::string
  read_file(const std::string &name)
  {
    std::ifstream     in(name);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  TEST(Plugins, RegisteredFromOutsideTheLibrary)
  {
    EXPECT_TRUE(Drivers::registry().has("test counting"));
    EXPECT_TRUE(Drivers::registry().has("static"));
    EXPECT_TRUE(Postprocess::registry<2>().has("test largest displacement"));
    EXPECT_TRUE(Fracture::registry<3>().has("max principal stress"));
    // The parameter file accepts the program's driver by its name.
    dealii::ParameterHandler prm;
    Parameters::Scene::declare(prm);
    prm.enter_subsection("Driver");
    EXPECT_NO_THROW(prm.set("Type", "test counting"));
    EXPECT_ANY_THROW(prm.set("Type", "no such driver"));
    prm.leave_subsection();
    prm.enter_subsection("Fracture");
    EXPECT_NO_THROW(prm.set("Criterion", "none"));
    EXPECT_NO_THROW(prm.set("Criterion", "critical stretch"));
    prm.leave_subsection();
  }

  TEST(Plugins, DriversThatSolveSayWhetherTheySolve)
  {
    // The drivers of equilibria solve with the tangent, so set-up builds
    // their preconditioner early (Coupling::Settings::prepare_solver); the
    // drivers of forces and of the assembled matrix do not.
    for (const std::string name : Drivers::registry().names())
      {
        const auto driver = Drivers::registry().create(name);
        ASSERT_TRUE(driver) << name;
        const bool solves = name == "static" || name == "quasi-static" ||
                            name == "newton" || name == "arc length";
        if (name != "test counting")
          EXPECT_EQ(driver->solves_linear_systems(), solves) << name;
      }
    EXPECT_TRUE(Drivers::registry().has("arc length"));
  }

  TEST(Plugins, UnknownNamesSuggestTheNearest)
  {
    const std::vector<std::string> names = {"static",
                                            "quasi-static",
                                            "newmark"};
    EXPECT_EQ(Plugins::nearest_name("quasistatic", names), "quasi-static");
    EXPECT_EQ(Plugins::nearest_name("Newmark", names), "newmark");
    EXPECT_EQ(Plugins::nearest_name("explicit", names), "");
    try
      {
        Drivers::create("quasistatic", "scene.prm");
        FAIL() << "an unknown driver was created";
      }
    catch (const InputError &e)
      {
        const std::string what = e.what();
        EXPECT_NE(what.find("Driver/Type"), std::string::npos) << what;
        EXPECT_NE(what.find("did you mean 'quasi-static'"), std::string::npos)
          << what;
      }
    EXPECT_THROW(Fracture::create_criterion<2>("mtcs", "scene.prm"),
                 InputError);
    EXPECT_EQ(Fracture::create_criterion<2>("none", "scene.prm"), nullptr);
  }

  TEST(Parameters, MisspeltEntrySuggestedWhateverTheFilesPath)
  {
    // deal.II wraps its report at a fixed width, so where the unknown name
    // falls depends on the length of the file's path; the suggestion must
    // not (CI, under a longer path, once lost it).
    const fs::path base = fs::temp_directory_path() / "pdfem_misspelt";
    fs::remove_all(base);
    for (unsigned int length = 1; length <= 48; ++length)
      {
        const fs::path folder = base / std::string(length, 'd');
        fs::create_directories(folder);
        const std::string file = (folder / "scene.prm").string();
        std::ofstream(file) << "set Dimension = 2\n"
                               "subsection Driver\n"
                               "  set Load stepz = 1\n"
                               "end\n";
        Parameters::Scene scene;
        try
          {
            scene.read(file);
            ADD_FAILURE() << "a misspelt entry was accepted";
          }
        catch (const InputError &e)
          {
            const std::string what = e.what();
            EXPECT_NE(what.find("did you mean 'Driver/Load steps'?"),
                      std::string::npos)
              << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
          }
      }
    fs::remove_all(base);
  }

  TEST(Plugins, EachPluginChecksItsCompatibility)
  {
    Drivers::RunTraits traits;
    traits.file        = "scene.prm";
    traits.model_name  = "pdlsm";
    traits.driver_name = "explicit";
    traits.has_mass    = false;
    // A dynamic driver asks for a mass, the newton driver for a nonlinear
    // model, mcts for a driver that is not dynamic.
    EXPECT_THROW(Drivers::create("explicit", "scene.prm")->check(traits),
                 InputError);
    traits.has_mass = true;
    EXPECT_NO_THROW(Drivers::create("explicit", "scene.prm")->check(traits));
    EXPECT_THROW(Drivers::create("newton", "scene.prm")->check(traits),
                 InputError);
    traits.nonlinear_model = true;
    EXPECT_NO_THROW(Drivers::create("newton", "scene.prm")->check(traits));
    EXPECT_THROW(Drivers::create("quasi-static", "scene.prm")->check(traits),
                 InputError);
    const auto mcts = Fracture::create_criterion<2>("mcts", "scene.prm");
    EXPECT_THROW(mcts->check({"scene.prm", true, "explicit"}), InputError);
    EXPECT_NO_THROW(mcts->check({"scene.prm", false, "quasi-static"}));
  }

  /// A pure FE bar pulled at its right end (1 MPa, E = 1 GPa, nu = 0),
  /// driven by the program's own driver, writing into @p folder.
  void
  make_pulled_bar(RunSetup<2> &setup, const MPI_Comm comm, const char *folder)
  {
    setup.name    = "plugins_test";
    setup.out_dir = (std::filesystem::temp_directory_path() / folder).string();
    std::filesystem::remove_all(setup.out_dir);
    dealii::GridGenerator::subdivided_hyper_rectangle(
      setup.create_triangulation(comm),
      {8, 2},
      dealii::Point<2>(0, 0),
      dealii::Point<2>(4, 1),
      true);
    auto &s                          = setup.settings;
    s.material.youngs_modulus        = 1e9;
    s.material.poissons_ratio        = 0.;
    s.material.plane_stress          = true;
    Coupling::BoundaryCondition<2> x = {}, y = {}, pull = {};
    x.name = "left", x.boundary_ids = {0}, x.component = 0, x.expression = "0";
    y.name = "bottom", y.boundary_ids = {2}, y.component = 1,
    y.expression = "0";
    pull.name = "right", pull.boundary_ids = {1}, pull.component = 0,
    pull.expression   = "1e6";
    s.dirichlet       = {x, y};
    s.traction        = {pull};
    setup.driver.type = "test counting";
    setup.write_vtu   = false;
  }

  /// A driver that does not say it can resume (Interface::resumable())
  /// refuses checkpoints before any work.
  TEST(Simulator, ADriverThatCannotResumeRefusesCheckpoints)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    RunSetup<2>    setup;
    make_pulled_bar(setup, comm, "pdfem_plugins_checkpoint_test");
    setup.checkpoint_steps = 2;
    try
      {
        Simulator<2> simulator(std::move(setup), comm);
        FAIL() << "checkpoints were accepted for a driver that cannot resume";
      }
    catch (const InputError &e)
      {
        const std::string what = e.what();
        EXPECT_NE(what.find("Output/Checkpoint steps: a run of Driver/Type = "
                            "test counting cannot be checkpointed"),
                  std::string::npos)
          << what;
      }
  }

  /// A program's run with no parameter file: a pure FE bar pulled at its
  /// right end, the program's own driver and postprocessor.
  TEST(Simulator, RunsAProgramsOwnSetUpAndPlugins)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    RunSetup<2>    setup;
    make_pulled_bar(setup, comm, "pdfem_plugins_test");
    const unsigned int before = CountingDriver::runs;

    Simulator<2> simulator(std::move(setup), comm);
    // The progress lines go to std::cout and leave its format as it was.
    std::ostringstream progress;
    std::streambuf    *cout_buffer = std::cout.rdbuf(progress.rdbuf());
    std::cout.precision(7);
    const int exit_code = simulator.run();
    std::cout.rdbuf(cout_buffer);
    EXPECT_EQ(exit_code, 0);
    EXPECT_EQ(std::cout.precision(), 7);
    std::cout.precision(6);
    EXPECT_NE(progress.str().find("Exit state: completed"), std::string::npos)
      << progress.str();
    EXPECT_EQ(CountingDriver::runs, before + 1);

    // u(4) = sigma L / E = 1e6 * 4 / 1e9 = 4e-3 (nu = 0, uniaxial).
    const std::string dir     = simulator.get_setup().out_dir;
    const std::string summary = read_file(dir + "/summary.json");
    EXPECT_NE(summary.find("\"driver\": \"test counting\""), std::string::npos)
      << summary;
    const auto at = summary.find("\"test_u_max\": ");
    ASSERT_NE(at, std::string::npos) << summary;
    EXPECT_NEAR(std::stod(summary.substr(at + 14)), 4e-3, 1e-9);
    const std::string history = read_file(dir + "/history.csv");
    EXPECT_NE(history.find("test_u_max"), std::string::npos) << history;
    EXPECT_NE(history.find("reaction_left_x"), std::string::npos) << history;
  }
} // namespace

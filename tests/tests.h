#ifndef periarlequin_tests_h
#define periarlequin_tests_h

// Helpers shared by the verification tests. A test asserts its physics itself: check() writes
// a deterministic line (the verdict and the tolerance, not noisy digits) to the file "output"
// that the test suite compares with the stored .output, prints the measured figures on stdout
// (kept beside it, shown when a test fails), and throws when the measured value is off.

#include <periarlequin/coupling/interpolation_operator.h>
#include <periarlequin/simulator.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

namespace PeriArlequinTests
{
  using namespace dealii;

  /** Build a simulator from parameter text; entries not given keep their defaults. */
  template <int dim>
  std::unique_ptr<PeriArlequin::Simulator<dim>>
  make_simulator(const std::string &parameters, const MPI_Comm communicator = MPI_COMM_WORLD)
  {
    ParameterHandler prm;
    PeriArlequin::Simulator<dim>::declare_parameters(prm);
    prm.parse_input_from_string(parameters);
    return std::make_unique<PeriArlequin::Simulator<dim>>(prm, communicator);
  }

  /**
   * Parameter text of subsection "Boundary conditions": a traction of @p stress [Pa] pulling
   * the faces normal to axis @p axis (boundary ids 2 axis and 2 axis + 1) apart (pushing them
   * together if negative), the others free.
   */
  inline std::string
  opposite_tractions(const double stress, const unsigned int dim, const unsigned int axis)
  {
    std::ostringstream text;
    text << "subsection Boundary conditions\n";
    for (const unsigned int side : {0, 1})
      {
        text << "  subsection Boundary " << 2 * axis + side
             << "\n    set Type = traction\n    subsection Function\n"
             << "      set Function expression = ";
        for (unsigned int d = 0; d < dim; ++d)
          text << (d > 0 ? "; " : "") << (d == axis ? (side == 0 ? -stress : stress) : 0.);
        text << "\n    end\n  end\n";
      }
    text << "end\n";
    return text.str();
  }

  /** opposite_tractions() on the y faces (boundary ids 2 and 3). */
  inline std::string
  opposite_y_tractions(const double stress, const unsigned int dim)
  {
    return opposite_tractions(stress, dim, 1);
  }

  /** Parameter text that silences files and progress: the deterministic test mode. */
  inline std::string
  quiet_output()
  {
    return "subsection Output\n"
           "  set Directory = test_output\n"
           "  set Output interval = 0\n"
           "  set Energy interval = 1\n"
           "  set Progress interval = 0\n"
           "  set Print timing summary = false\n"
           "end\n";
  }

  /**
   * Parameter text of a quasi-static run (Time/Integration = quasi-static, load increments of
   * 1 s to @p end_time, static solves to 1e-5) in the deterministic test mode, recording the
   * energies and the support reactions; @p time_step is that of the case's explicit
   * estimates.
   */
  inline std::string
  quasi_static_controls(const double time_step, const double end_time)
  {
    std::ostringstream text;
    text << "subsection Time\n  set Integration = quasi-static\n  set Time step = " << time_step
         << "\n  set End time = " << end_time << "\nend\n"
         << "subsection Static solve\n  set Tolerance = 1e-5\n  set Load step = 1\nend\n"
         << quiet_output()
         << "subsection Postprocess\n  set List of postprocessors = energies, support "
            "reactions\nend\n";
    return text.str();
  }

  /**
   * A pure PD block of 1 mm lattice spacing (2D: 20 mm square, 3D: 10 mm cube) with a
   * pre-crack from the left side to the middle, displaced at rest by a smooth random-looking
   * field of strain about 1e-2; @p model is the two-dimensional model (2D; empty: default).
   * Used to check identities of the PD forces and energies on broken bonds, surfaces and the
   * deviatoric-moment term they activate.
   */
  template <int dim>
  std::string
  cracked_random_block(const std::string &model = "")
  {
    std::ostringstream prm;
    prm << "set Dimension = " << dim << "\n"
        << "subsection Geometry\n  set Lower corner = " << (dim == 2 ? "0, 0" : "0, 0, 0")
        << "\n  set Upper corner = " << (dim == 2 ? "0.02, 0.02" : "0.01, 0.01, 0.01")
        << "\n  set Subdivisions = " << (dim == 2 ? "5, 5" : "2, 2, 2") << "\nend\n"
        << (dim == 2 && !model.empty() ?
              "subsection Material\n  set Two-dimensional model = " + model + "\nend\n" :
              "")
        << "subsection Peridynamics\n  set Region = "
        << (dim == 2 ? "0, 0 : 0.02, 0.02" : "0, 0, 0 : 0.01, 0.01, 0.01")
        << "\n  set Lattice spacing = 1e-3\n"
        << "  set Pre-cracks = "
        << (dim == 2 ? "0, 0.0101 : 0.01, 0.0101" : "0, 0.0051, 0 : 0.005, 0, 0 : 0, 0, 0.01")
        << "\nend\n"
        << "subsection Time\n  set Time step = 1e-9\n  set Stability estimate iterations = 5\nend\n"
        << "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
        << "    set Function expression = 1e-5*sin(7e3*x*y+3e2*y+1); 1e-5*cos(5e3*x+4e5*x*y)"
        << (dim == 3 ? "; 1e-5*sin(3e3*z+2e5*x*y+9e2*x)" : "") << "\n  end\nend\nend\n"
        << quiet_output();
    return prm.str();
  }

  inline bool
  is_root()
  {
    return Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  /** Write @p triangulation as a Gmsh file @p file_name on rank 0; every rank waits for it. */
  template <int dim>
  void
  write_gmsh_on_root(const Triangulation<dim> &triangulation, const std::string &file_name)
  {
    if (is_root())
      {
        GridOut writer;
        writer.set_flags(GridOutFlags::Msh(true));
        std::ofstream file(file_name);
        file.precision(16);
        writer.write_msh(triangulation, file);
      }
    MPI_Barrier(MPI_COMM_WORLD);
  }

  /** Stop a test that compares several ranks with one when run on one rank. */
  inline void
  require_several_ranks()
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) >= 2,
                ExcMessage("this test runs on 2 or more ranks"));
  }

  /**
   * Stop unless this rank runs 2 threads: a comparison of 2 threads against 1 would pass
   * vacuously on one (run_test(..., 2) asks for them; DEAL_II_NUM_THREADS may cap them).
   */
  inline void
  require_two_threads()
  {
    AssertThrow(MultithreadInfo::n_threads() == 2,
                ExcMessage("the test needs 2 threads (DEAL_II_NUM_THREADS below 2?)"));
  }

  /**
   * Call @p work with deal.II limited to one thread, as DEAL_II_NUM_THREADS=1 does, then lift
   * the limit: deal.II then takes its serial paths (a loop is one range, FEValues reuse the
   * geometry of a translated cell), not only one task at a time as in a one-thread TBB arena.
   */
  template <typename Work>
  void
  on_one_thread(const Work &work)
  {
    MultithreadInfo::set_thread_limit(1);
    work();
    MultithreadInfo::set_thread_limit();
    require_two_threads();
  }

  /** The verdict file on rank 0. */
  inline std::ostream &
  verdicts()
  {
    static std::ofstream file(is_root() ? "output" : "/dev/null");
    return file;
  }

  /** Measured figures for a human reader, on rank 0. */
  inline void
  report(const std::string &what, const double value)
  {
    if (is_root())
      std::cout << what << " = " << std::setprecision(10) << value << std::endl;
  }

  /** Assert |measured - expected| <= tolerance (absolute), printing the verdict. */
  inline void
  check(const std::string &what,
        const double       measured,
        const double       expected,
        const double       tolerance)
  {
    const bool ok = std::abs(measured - expected) <= tolerance;
    report(what + " (measured)", measured);
    report(what + " (expected)", expected);
    verdicts() << what << ": " << (ok ? "within" : "OUTSIDE") << " tolerance " << tolerance
               << std::endl;
    if (!ok)
      {
        std::ostringstream message;
        message << what << ": measured " << measured << ", expected " << expected << " +- "
                << tolerance;
        throw std::runtime_error(message.str());
      }
  }

  /** Assert measured < bound, printing the verdict. */
  inline void
  check_below(const std::string &what, const double measured, const double bound)
  {
    const bool ok = measured < bound;
    report(what + " (measured)", measured);
    verdicts() << what << ": " << (ok ? "below" : "NOT below") << " " << bound << std::endl;
    if (!ok)
      {
        std::ostringstream message;
        message << what << ": measured " << measured << ", not below " << bound;
        throw std::runtime_error(message.str());
      }
  }
  /**
   * For each DoF of the FE zone, the coordinate along its own component direction (x for
   * x-displacement DoFs...) and, in @p is_x_component, 1 for x-displacement DoFs, else 0.
   */
  template <int dim>
  void
  dof_coordinates(const PeriArlequin::FEZone<dim>            &fe_zone,
                  LinearAlgebra::distributed::Vector<double> &coordinate,
                  LinearAlgebra::distributed::Vector<double> &is_x_component)
  {
    fe_zone.initialize_vector(coordinate);
    fe_zone.initialize_vector(is_x_component);
    class Position : public Function<dim>
    {
    public:
      Position()
        : Function<dim>(dim)
      {}
      double
      value(const Point<dim> &p, const unsigned int c) const override
      {
        return p[c];
      }
    };
    fe_zone.interpolate(Position(), coordinate);
    Vector<double> unit_x(dim);
    unit_x(0) = 1;
    fe_zone.interpolate(Functions::ConstantFunction<dim>(unit_x), is_x_component);
  }
  /**
   * Call @p visit(local DoF index, support point, component) for every locally owned DoF of
   * the FE zone of @p simulator; nothing if the case has no FE zone.
   */
  template <int dim, typename Visitor>
  void
  for_each_fe_dof(const PeriArlequin::Simulator<dim> &simulator, const Visitor &visit)
  {
    if (!simulator.has_fe_zone())
      return;
    std::vector<unsigned int> dofs, components;
    std::vector<Point<dim>>   points;
    simulator.get_fe_zone().support_points(dofs, points, components);
    for (unsigned int k = 0; k < dofs.size(); ++k)
      visit(dofs[k], points[k], components[k]);
  }

  /** Euclidean distance from @p x to the box [@p lower, @p upper] (0 inside). */
  template <int dim>
  double
  distance_to_box(const Point<dim> &x, const Point<dim> &lower, const Point<dim> &upper)
  {
    Tensor<1, dim> gap;
    for (unsigned int d = 0; d < dim; ++d)
      gap[d] = std::max({lower[d] - x[d], 0., x[d] - upper[d]});
    return gap.norm();
  }

  /**
   * The vector field @p field interpolated on the FE DoFs of @p simulator (set up) and then
   * to its PD particles in FE cells (alpha > 0) by the interpolation N: the largest error
   * against @p field at the particles, relative to the field's largest magnitude there,
   * over all ranks. Reports the number of particles.
   */
  template <int dim>
  double
  interpolation_error_at_particles(const PeriArlequin::Simulator<dim> &simulator,
                                   const Function<dim>                &field)
  {
    const auto                                &fe = simulator.get_fe_zone();
    const auto                                &pd = *simulator.get_pd_zone();
    LinearAlgebra::distributed::Vector<double> u;
    fe.initialize_vector(u);
    fe.interpolate(field, u);
    u.update_ghost_values();
    std::vector<unsigned int> coupled;
    const auto                alpha = pd.blending_weights();
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (alpha[i] > 0)
        coupled.push_back(i);
    PeriArlequin::InterpolationOperator<dim> interpolation;
    interpolation.reinit(fe, pd, coupled);
    const auto x     = pd.reference_positions();
    double     worst = 0, magnitude = 0;
    for (unsigned int r = 0; r < coupled.size(); ++r)
      {
        const Tensor<1, dim> value = interpolation.interpolate(u, r);
        for (unsigned int c = 0; c < dim; ++c)
          {
            const double exact = field.value(x[coupled[r]], c);
            worst              = std::max(worst, std::abs(value[c] - exact));
            magnitude          = std::max(magnitude, std::abs(exact));
          }
      }
    report("particles interpolated", Utilities::MPI::sum(coupled.size(), MPI_COMM_WORLD));
    return Utilities::MPI::max(worst, MPI_COMM_WORLD) /
           Utilities::MPI::max(magnitude, MPI_COMM_WORLD);
  }

  /** Assert measured > bound, printing the verdict. */
  inline void
  check_above(const std::string &what, const double measured, const double bound)
  {
    const bool ok = measured > bound;
    report(what + " (measured)", measured);
    verdicts() << what << ": " << (ok ? "above" : "NOT above") << " " << bound << std::endl;
    if (!ok)
      {
        std::ostringstream message;
        message << what << ": measured " << measured << ", not above " << bound;
        throw std::runtime_error(message.str());
      }
  }

  /** Parameter text of a box "lower : upper" in the PD region syntax. */
  template <int dim>
  std::string
  box_text(const Point<dim> &lower, const Point<dim> &upper)
  {
    std::ostringstream text;
    text << std::setprecision(17);
    for (unsigned int d = 0; d < dim; ++d)
      text << (d ? ", " : "") << lower[d];
    text << " : ";
    for (unsigned int d = 0; d < dim; ++d)
      text << (d ? ", " : "") << upper[d];
    return text.str();
  }

  /**
   * The largest difference between the energy histories @p history and @p reference, per
   * column relative to the column's largest magnitude in @p reference (columns that stay 0
   * are compared absolutely: any difference there counts as 1); the magnitudes reported
   * under @p title.
   */
  inline double
  history_difference(const PeriArlequin::EnergyHistory &history,
                     const PeriArlequin::EnergyHistory &reference,
                     const std::string                 &title)
  {
    const auto &rows = history.rows(), &reference_rows = reference.rows();
    AssertThrow(reference_rows.size() == rows.size(),
                ExcMessage("the runs recorded different numbers of steps"));
    double worst = 0;
    for (unsigned int c = 0; c < rows.front().size(); ++c)
      {
        double magnitude = 0, difference = 0;
        for (unsigned int n = 0; n < rows.size(); ++n)
          {
            magnitude  = std::max(magnitude, std::abs(reference_rows[n][c]));
            difference = std::max(difference, std::abs(rows[n][c] - reference_rows[n][c]));
          }
        report(title + " " + history.column_names()[c] + " largest magnitude", magnitude);
        worst =
          std::max(worst, magnitude > 0 ? difference / magnitude : (difference > 0 ? 1. : 0.));
      }
    return worst;
  }

  /**
   * The largest difference between the columns @p columns of two energy histories over their
   * records: absolute, or, if @p relative, over each column's largest magnitude in
   * @p reference.
   */
  inline double
  largest_column_difference(const PeriArlequin::EnergyHistory &history,
                            const PeriArlequin::EnergyHistory &reference,
                            const std::vector<std::string>    &columns,
                            const bool                         relative)
  {
    double worst = 0;
    for (const std::string &column : columns)
      {
        const auto a = history.column(column), b = reference.column(column);
        AssertThrow(a.size() == b.size(),
                    ExcMessage("the runs recorded different numbers of steps"));
        double magnitude = 0, difference = 0;
        for (unsigned int n = 0; n < a.size(); ++n)
          {
            magnitude  = std::max(magnitude, std::abs(b[n]));
            difference = std::max(difference, std::abs(a[n] - b[n]));
          }
        worst = std::max(worst, relative && magnitude > 0 ? difference / magnitude : difference);
      }
    return worst;
  }

  /**
   * @p run, a finished run of the case @p parameters on all ranks, against the same case run
   * here on rank 0 alone (MPI_COMM_SELF): the largest absolute difference over the columns
   * @p counts and the largest relative one (over each column's largest magnitude) over
   * @p values; the same on every rank.
   */
  template <int dim>
  std::pair<double, double>
  differences_from_rank_0_alone(const PeriArlequin::Simulator<dim> &run,
                                const std::string                  &parameters,
                                const std::vector<std::string>     &counts,
                                const std::vector<std::string>     &values)
  {
    double count_difference = 0, value_difference = 0;
    if (is_root())
      {
        auto serial = make_simulator<dim>(parameters, MPI_COMM_SELF);
        serial->run();
        const auto &history   = run.get_energy_history();
        const auto &reference = serial->get_energy_history();
        count_difference      = largest_column_difference(history, reference, counts, false);
        value_difference      = largest_column_difference(history, reference, values, true);
      }
    return {Utilities::MPI::broadcast(MPI_COMM_WORLD, count_difference, 0),
            Utilities::MPI::broadcast(MPI_COMM_WORLD, value_difference, 0)};
  }

  /** That the finished run @p simulator changed column @p column (the case is not vacuous). */
  template <int dim>
  void
  require_active_column(const PeriArlequin::Simulator<dim> &simulator,
                        const std::string                  &title,
                        const std::string                  &column)
  {
    const double last = simulator.get_energy_history().column(column).back();
    report(title + " " + column + " at the end", last);
    AssertThrow(last != 0, ExcMessage(title + ": " + column + " stayed 0, the case is vacuous"));
  }

  /**
   * Run the case given by @p parameters on all ranks and, on rank 0 alone (MPI_COMM_SELF),
   * once more; return history_difference() of the two (the same on every rank). If
   * @p active_column is given, that column must end non-zero (e.g. broken_bonds: the case did
   * break bonds).
   */
  template <int dim>
  double
  parallel_vs_serial_history_difference(const std::string &parameters,
                                        const std::string &title,
                                        const std::string &active_column = "")
  {
    auto parallel = make_simulator<dim>(parameters, MPI_COMM_WORLD);
    parallel->run();
    if (!active_column.empty())
      require_active_column(*parallel, title, active_column);
    double worst = 0;
    if (is_root())
      {
        auto serial = make_simulator<dim>(parameters, MPI_COMM_SELF);
        serial->run();
        worst =
          history_difference(parallel->get_energy_history(), serial->get_energy_history(), title);
      }
    return Utilities::MPI::max(worst, MPI_COMM_WORLD);
  }

  /**
   * A growing zone on all ranks against rank 0 alone: @p parallel, a finished run of the case
   * @p parameters on MPI_COMM_WORLD, and the same case run here on MPI_COMM_SELF must break
   * the same bonds, convert the same cells and hold the same particles at every record, and
   * agree in crack area and total energy to 1e-10 of their magnitude (sums in another order).
   */
  template <int dim>
  void
  check_growth_matches_rank_0(const PeriArlequin::Simulator<dim> &parallel,
                              const std::string                  &parameters)
  {
    const auto &history = parallel.get_energy_history();
    double      counts = 0, energies = 0;
    if (is_root())
      {
        auto serial = make_simulator<dim>(parameters, MPI_COMM_SELF);
        serial->run();
        const auto &reference = serial->get_energy_history();
        counts                = largest_column_difference(history,
                                           reference,
                                           {"broken_bonds", "converted_cells", "pd_particles"},
                                           false);
        energies =
          largest_column_difference(history, reference, {"crack_area", "total_energy"}, true);
      }
    check_below("largest |broken bonds, converted cells, particles: all ranks - rank 0 alone|",
                Utilities::MPI::broadcast(MPI_COMM_WORLD, counts, 0),
                1e-15);
    check_below("largest relative |crack area, total energy: all ranks - rank 0 alone|",
                Utilities::MPI::broadcast(MPI_COMM_WORLD, energies, 0),
                1e-10);
  }

  /**
   * Energy conservation of a finished run: the largest |total energy - initial total| over
   * the history, relative to the largest mechanical energy reached (loads may pump energy
   * in), must stay below @p bound; and, so that the check is not vacuous, kinetic and strain
   * energy must be exchanged (the kinetic energy drops below 0.8 of that scale at times).
   */
  template <int dim>
  void
  check_energy_conservation(const std::string                  &name,
                            const PeriArlequin::Simulator<dim> &simulator,
                            const unsigned int                  n_steps,
                            const double                        bound)
  {
    report(name + " time step / stable step",
           simulator.get_time_step() / simulator.get_stable_time_step());
    const auto &history = simulator.get_energy_history();
    const auto  total   = history.column("total_energy");
    const auto  kinetic = history.column("kinetic_energy");
    const auto  strain  = history.column("strain_energy");
    AssertThrow(total.size() == n_steps + 1,
                ExcMessage("expected " + std::to_string(n_steps) + " recorded steps"));
    double scale = 0, drift = 0;
    for (unsigned int n = 0; n < total.size(); ++n)
      {
        scale = std::max(scale, kinetic[n] + strain[n]);
        drift = std::max(drift, std::abs(total[n] - total.front()));
      }
    report(name + " energy scale", scale);
    check_below(name + ": min kinetic / energy scale",
                *std::min_element(kinetic.begin(), kinetic.end()) / scale,
                0.8);
    check_below(name + ": max |total energy drift| / energy scale", drift / scale, bound);
  }

  /**
   * Run a test body under MPI with at most @p n_threads threads per rank; a failed check or
   * any error gives exit code 1. On several
   * ranks a failure ends all of them (MPI_Abort): a rank that failed alone would otherwise
   * leave the others waiting in their next collective call.
   */
  template <typename Body>
  int
  run_test(int argc, char **argv, const Body &body, const unsigned int n_threads = 1)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, n_threads);
    try
      {
        body();
      }
    catch (const std::exception &error)
      {
        std::cerr << "Test failed: " << error.what() << std::endl;
        if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
          MPI_Abort(MPI_COMM_WORLD, 1);
        return 1;
      }
    return 0;
  }
} // namespace PeriArlequinTests

#endif

#include <periarlequin/base/crack_tip_field.h>
#include <periarlequin/base/gather.h>
#include <periarlequin/postprocess/crack_diagnostics.h>
#include <periarlequin/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/set.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  void
  CrackDiagnostics<dim>::entries(ParameterEntries &entries)
  {
    entries.add("Damage threshold",
                damage_threshold,
                Patterns::Double(0, 1),
                "Damage from which a particle counts as cracked [-]. A particle next to the "
                "faces of a straight crack has a damage near 0.5.");
    entries.add("Link distance",
                link_distance,
                Patterns::Double(1),
                "Cracked particles at most this far apart belong to one crack [lattice "
                "spacings].");
    entries.add("Branch separation",
                branch_separation,
                Patterns::Double(0),
                "A tip is the particle farthest along its crack within this distance; two "
                "branches are told apart once their tips are farther apart [horizons].");
    entries.add("Speed window",
                speed_window,
                Patterns::Integer(1),
                "Tip speeds are least-squares slopes of the path length over this many "
                "recorded intervals (Output/Energy interval steps each) [-].");
    entries.add("Reported branches",
                reported_branches,
                Patterns::Integer(1, 64),
                "Branches given columns in the history, in the order they appeared [-].");
    entries.add_parsed<std::optional<Point<dim>>>(
      "Initial tip",
      initial_tip,
      "",
      [](const std::string &text, const std::string &path) -> std::optional<Point<dim>> {
        if (text.empty())
          return {};
        const std::vector<std::string> coordinates = Utilities::split_string_list(text);
        bool                           valid       = coordinates.size() == dim;
        for (unsigned int d = 0; valid && d < dim; ++d)
          valid = Patterns::Double().match(coordinates[d]);
        if (!valid)
          throw_invalid_parameter(path,
                                  text,
                                  "empty or " + std::to_string(dim) + " coordinates 'x, y" +
                                    (dim == 3 ? ", z" : "") + "' [m]");
        Point<dim> tip;
        for (unsigned int d = 0; d < dim; ++d)
          tip[d] = Utilities::string_to_double(coordinates[d]);
        return tip;
      },
      "Tip of the pre-crack whose initiation and kink are followed, 'x, y[, z]' [m] (in 3D "
      "only x and y count: the front runs along z). Empty: none. Adds the columns "
      "initiation_time (first new broken bond of a particle within a horizon of the tip), "
      "growth_time (first new cracked particle a horizon or more ahead of it), kink_angle "
      "[deg] and kink_particles, and, when the boundaries carry a crack-tip field, its K_I, "
      "K_II [Pa m^1/2] and G [J/m^2] now and at initiation and growth.");
    entries.add("Initial direction",
                initial_direction,
                Patterns::Double(-360, 360),
                "Direction in which the pre-crack points at its tip, from the x axis [deg]; "
                "kink angles are measured from it, counter-clockwise positive.");
    entries.add_parsed<std::array<double, 2>>(
      "Kink fit range",
      kink_fit_range,
      "1, 5",
      [](const std::string &text, const std::string &path) {
        const std::vector<std::string> values = Utilities::split_string_list(text);
        const bool                     valid =
          Patterns::List(Patterns::Double(0), 2, 2).match(text) &&
          Utilities::string_to_double(values[1]) > Utilities::string_to_double(values[0]);
        if (!valid)
          throw_invalid_parameter(path,
                                  text,
                                  "two distances, the second larger than the first [horizons]");
        return std::array<double, 2>{
          {Utilities::string_to_double(values[0]), Utilities::string_to_double(values[1])}};
      },
      "Least and largest distance from the initial tip of the new cracked particles whose "
      "line through the tip gives the kink angle [horizons].");
  }

  template <int dim>
  void
  CrackDiagnostics<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<CrackDiagnostics<dim>>(prm);
  }

  template <int dim>
  void
  CrackDiagnostics<dim>::parse_parameters(ParameterHandler &prm)
  {
    ParameterEntries::parse_here(prm, *this, "Postprocess/cracks/");
  }

  template <int dim>
  void
  CrackDiagnostics<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const PDZone<dim> *pd = simulator.get_pd_zone();
    AssertThrow(pd != nullptr,
                ExcMessage("Invalid input: 'Postprocess/List of postprocessors' names 'cracks' "
                           "but the case has no PD zone (Peridynamics/Region is empty)."));
    const auto    &parameters   = pd->get_parameters();
    const MPI_Comm communicator = pd->get_communicator();
    if (!tracker)
      tracker = std::make_unique<CrackTracker<dim>>(link_distance * parameters.lattice_spacing,
                                                    branch_separation * parameters.horizon());
    if (!initiation && initial_tip)
      {
        initiation =
          std::make_unique<CrackInitiation<dim>>(*initial_tip,
                                                 initial_direction * numbers::PI / 180.,
                                                 parameters.horizon(),
                                                 std::array<double, 2>{
                                                   {kink_fit_range[0] * parameters.horizon(),
                                                    kink_fit_range[1] * parameters.horizon()}});
        load_at_initiation.fill(std::numeric_limits<double>::quiet_NaN());
        load_at_growth.fill(std::numeric_limits<double>::quiet_NaN());
      }

    // Gathered as (id, position, damage) rows of doubles: ids are lattice site numbers,
    // exact in a double.
    using Cracked = typename CrackTracker<dim>::CrackedParticle;
    std::vector<double> local;
    const auto          ids = pd->particle_ids();
    const auto          x   = pd->reference_positions();
    for (const auto &[i, damage] : pd->get_bonds().damaged_particles())
      if (!pd->is_slave(i))
        {
          local.push_back(ids[i]);
          for (unsigned int d = 0; d < dim; ++d)
            local.push_back(x[i][d]);
          local.push_back(damage);
        }
    damaged.clear();
    const std::vector<double> all = gather_values(local, communicator);
    for (std::size_t k = 0; k < all.size(); k += dim + 2)
      {
        Cracked particle{static_cast<types::particle_index>(all[k]), Point<dim>()};
        for (unsigned int d = 0; d < dim; ++d)
          particle.position[d] = all[k + 1 + d];
        damaged.emplace_back(particle, all[k + dim + 1]);
      }
    std::sort(damaged.begin(), damaged.end(), [](const auto &a, const auto &b) {
      return a.first.id < b.first.id;
    });
    std::vector<Cracked> cracked;
    for (const auto &[particle, d] : damaged)
      if (d >= damage_threshold)
        cracked.push_back(particle);
    tracker->update(simulator.get_time(), cracked);

    const double area = broken_bond_area(pd->get_bonds(), parameters.lattice_spacing, communicator);
    if (simulator.get_step_number() == 0)
      initial_area = area;
    history.add_value("branches", tracker->n_active_branches());
    history.add_value("crack_extension", tracker->crack_extension());
    history.add_value("crack_area", area - initial_area);
    history.add_value("broken_bond_energy", parameters.energy_release_rate * (area - initial_area));
    const auto  &branches = tracker->get_branches();
    const double nan      = std::numeric_limits<double>::quiet_NaN();
    const char  *axes[3]  = {"x", "y", "z"};
    for (unsigned int b = 0; b < reported_branches; ++b)
      {
        const bool        shown  = b < branches.size() && branches[b].active;
        const std::string prefix = "branch_" + std::to_string(b) + "_";
        for (unsigned int d = 0; d < dim; ++d)
          history.add_value(prefix + axes[d], shown ? branches[b].tips.back()[d] : nan);
        history.add_value(prefix + "path_length", shown ? branches[b].path_lengths.back() : nan);
        history.add_value(prefix + "speed", shown ? branches[b].speed(speed_window) : nan);
      }

    if (initiation)
      report_initiation(simulator, cracked, history);

    const unsigned int interval = simulator.get_output_parameters().output_interval;
    const unsigned int step     = simulator.get_step_number();
    if (interval > 0 && (step % interval == 0 || step == simulator.get_n_steps()))
      write_damage_map(simulator);
  }

  template <int dim>
  std::string
  CrackDiagnostics<dim>::save_state() const
  {
    std::ostringstream bytes;
    {
      boost::archive::binary_oarchive archive(bytes);
      const bool has_tracker = tracker != nullptr, has_initiation = initiation != nullptr;
      archive << has_tracker << has_initiation << initial_area;
      if (has_tracker)
        archive << *tracker;
      if (has_initiation)
        {
          archive << *initiation;
          for (const auto *loads : {&load_at_initiation, &load_at_growth})
            archive << (*loads)[0] << (*loads)[1] << (*loads)[2];
        }
    }
    return bytes.str();
  }

  template <int dim>
  void
  CrackDiagnostics<dim>::load_state(const std::string &state)
  {
    std::istringstream              bytes(state);
    boost::archive::binary_iarchive archive(bytes);
    bool                            has_tracker = false, has_initiation = false;
    archive >> has_tracker >> has_initiation >> initial_area;
    tracker.reset();
    initiation.reset();
    if (has_tracker)
      {
        tracker = std::make_unique<CrackTracker<dim>>(0., 0.);
        archive >> *tracker;
      }
    if (has_initiation)
      {
        initiation = std::make_unique<CrackInitiation<dim>>(Point<dim>(),
                                                            0.,
                                                            0.,
                                                            std::array<double, 2>{{0., 0.}});
        archive >> *initiation;
        for (auto *loads : {&load_at_initiation, &load_at_growth})
          archive >> (*loads)[0] >> (*loads)[1] >> (*loads)[2];
      }
  }

  template <int dim>
  void
  CrackDiagnostics<dim>::report_initiation(
    const Simulator<dim>                                           &simulator,
    const std::vector<typename CrackTracker<dim>::CrackedParticle> &cracked,
    EnergyHistory                                                  &history)
  {
    const PDZone<dim> &pd              = *simulator.get_pd_zone();
    const auto        &bonds           = pd.get_bonds();
    const auto         x               = pd.reference_positions();
    unsigned long long broken_near_tip = 0;
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (initiation->distance_from_tip(x[i]) <= pd.get_parameters().horizon())
        for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
          broken_near_tip += bonds.state[n] == BondFamilies<dim>::broken;
    const double before = initiation->initiation_time(), growth_before = initiation->growth_time();
    const double time = simulator.get_time();
    initiation->update(time, cracked, Utilities::MPI::sum(broken_near_tip, pd.get_communicator()));

    const CrackTipField<dim> *field = nullptr;
    for (const auto &condition : simulator.get_problem_data().boundary_conditions)
      if (const auto tip_field = dynamic_cast<const CrackTipField<dim> *>(condition.function.get()))
        field = tip_field;
    std::array<double, 3> load;
    load.fill(std::numeric_limits<double>::quiet_NaN());
    if (field)
      {
        const auto K = field->stress_intensity_factors(time);
        load         = {{K[0], K[1], field->energy_release_rate(time)}};
      }
    const bool initiated = std::isnan(before) && !std::isnan(initiation->initiation_time());
    const bool grown     = std::isnan(growth_before) && !std::isnan(initiation->growth_time());
    if (initiated)
      load_at_initiation = load;
    if (grown)
      load_at_growth = load;
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(pd.get_communicator()) == 0);
    for (const auto &[happened, what, values] :
         {std::make_tuple(initiated, "initiation", load_at_initiation),
          std::make_tuple(grown, "growth by a horizon", load_at_growth)})
      if (happened)
        {
          pcout << "Crack " << what << " at t = " << time << " s";
          if (field)
            pcout << ": K_I = " << values[0] << ", K_II = " << values[1]
                  << " Pa m^1/2, G = " << values[2] << " J/m^2";
          pcout << std::endl;
        }

    history.add_value("initiation_time", initiation->initiation_time());
    history.add_value("growth_time", initiation->growth_time());
    history.add_value("kink_angle", initiation->kink_angle() * 180. / numbers::PI);
    history.add_value("kink_particles", initiation->n_fitted_particles());
    if (field)
      {
        const char *names[3] = {"K_I", "K_II", "G"};
        for (unsigned int k = 0; k < 3; ++k)
          {
            history.add_value(names[k], load[k]);
            history.add_value(std::string("initiation_") + names[k], load_at_initiation[k]);
            history.add_value(std::string("growth_") + names[k], load_at_growth[k]);
          }
      }
  }

  template <int dim>
  void
  CrackDiagnostics<dim>::write_damage_map(const Simulator<dim> &simulator) const
  {
    if (Utilities::MPI::this_mpi_process(simulator.get_pd_zone()->get_communicator()) != 0)
      return;
    const auto        &output = simulator.get_output_parameters();
    std::ostringstream name;
    name << output.directory << "/" << output.base_name << "_damage_" << std::setw(6)
         << std::setfill('0') << simulator.get_step_number() << ".csv";
    std::ofstream file(name.str());
    AssertThrow(file, ExcMessage("Cannot write " + name.str()));
    const Box<dim> &domain = simulator.get_pd_zone()->get_domain();
    file << "# t = " << std::setprecision(10) << simulator.get_time() << " s; domain";
    for (const Point<dim> &corner : {domain.lower, domain.upper})
      for (unsigned int d = 0; d < dim; ++d)
        file << ' ' << corner[d];
    file << '\n';
    file << (dim == 2 ? "x,y,damage\n" : "x,y,z,damage\n") << std::setprecision(8);
    for (const auto &[particle, d] : damaged)
      {
        for (unsigned int c = 0; c < dim; ++c)
          file << particle.position[c] << ',';
        file << d << '\n';
      }
  }

  template class CrackDiagnostics<2>;
  template class CrackDiagnostics<3>;

  PERIARLEQUIN_REGISTER_POSTPROCESSOR(
    CrackDiagnostics,
    "cracks",
    "branches, tip position, path length and speed of each branch, crack area and the "
    "energy of the broken bonds; damage maps as CSV with the ParaView output")
} // namespace PeriArlequin

#ifndef periarlequin_fe_contact_checks_h
#define periarlequin_fe_contact_checks_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/fe/fe_zone.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <string>

// The input checks the contact models share (source/fe/contact.cc and
// elastic_target_contact.cc).
namespace PeriArlequin
{
  namespace internal
  {
    /** A set of ids as a parameter list. */
    inline std::string
    prm_list(const std::set<unsigned int> &ids)
    {
      std::string text;
      for (const unsigned int id : ids)
        text += (text.empty() ? "" : ", ") + std::to_string(id);
      return text;
    }

    /** Refuse boundary ids the mesh does not have, naming @p parameter. */
    template <int dim>
    void
    check_boundary_ids(const FEZone<dim>            &zone,
                       const std::set<unsigned int> &ids,
                       const std::string            &parameter)
    {
      const auto present = zone.get_dof_handler().get_triangulation().get_boundary_ids();
      for (const unsigned int id : ids)
        if (std::find(present.begin(), present.end(), id) == present.end())
          {
            std::ostringstream allowed;
            allowed << "boundary ids the mesh has (";
            for (unsigned int k = 0; k < present.size(); ++k)
              allowed << (k > 0 ? ", " : "") << present[k];
            allowed << "; a box has 0/1 on its x faces, 2/3 on y, 4/5 on z)";
            throw_invalid_parameter(parameter, std::to_string(id), allowed.str());
          }
    }

    /** Contact acts on vertices: FE_Q(1)^dim with lumped masses. */
    template <int dim>
    void
    check_linear_elements(const FEZone<dim> &zone, const std::string &model)
    {
      for (const auto &cell : zone.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
          {
            AssertThrow(cell->get_fe().degree == 1,
                        ExcMessage("Invalid input: 'Contact/Model' = " + model +
                                   " needs 'Finite elements/Polynomial degree' = 1 (lumped "
                                   "vertex masses)."));
            return;
          }
    }
  } // namespace internal
} // namespace PeriArlequin

#endif

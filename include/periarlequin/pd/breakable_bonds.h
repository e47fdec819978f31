#ifndef periarlequin_pd_breakable_bonds_h
#define periarlequin_pd_breakable_bonds_h

#include <periarlequin/pd/bond_families.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/tensor.h>

#include <cstddef>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The bonds as a fracture criterion sees them in one step: the intact bonds stored for
   * the owned particles (unbreakable ones left out), each with its extension under the
   * current displacements, and a way to break one. The PD zone refreshes its views of the
   * bonds (the stencil masks) after the criterion is done when a bond broke, so a criterion
   * neither touches the storage nor keeps any bookkeeping.
   *
   * A bond to a ghost particle is held by two ranks, which must decide alike: decide from
   * the bond's reference vector, its extension (bit-identical from both ends) and symmetric
   * functions of the ends' particle scalars.
   */
  template <int dim>
  class BreakableBonds
  {
  public:
    /** One intact, breakable bond as visited. */
    struct Bond
    {
      /** The owned particle that stores it and its neighbour (owned or ghost), local indices. */
      unsigned int particle, neighbor;
      /** The bond's number in the storage, as in PDMaterialModel::compute_pair_energies(). */
      std::size_t index;
      /** Reference vector xi (particle to neighbour), length |xi| and V_J v_IJ. */
      const typename BondFamilies<dim>::StencilEntry &reference;
      /** The displacements of the view (owned and ghost particles). */
      ArrayView<const Tensor<1, dim>> displacement;

      /**
       * e = |xi + eta| - |xi| [m], computed when asked (a criterion that decides on something
       * else first pays for it only where it matters).
       */
      double
      extension() const
      {
        return BondFamilies<dim>::extension(reference,
                                            displacement[neighbor] - displacement[particle])
          .first;
      }
    };

    /** The bonds of @p bonds under @p displacement (owned and ghost particles). */
    BreakableBonds(BondFamilies<dim> &bonds, ArrayView<const Tensor<1, dim>> displacement)
      : bonds(bonds)
      , displacement(displacement)
    {}

    /** Call @p visit(const Bond &) for every intact, breakable bond, in storage order. */
    template <typename Visitor>
    void
    for_each_intact(const Visitor &visit) const
    {
      for (unsigned int i = 0; i < bonds.n_owned; ++i)
        for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
          if (bonds.state[n] == BondFamilies<dim>::intact)
            {
              visit(Bond{i,
                         bonds.neighbor(i, n),
                         n,
                         bonds.stencil[bonds.stencil_index[n]],
                         displacement});
            }
    }

    /** Break @p bond for good. */
    void
    break_bond(const Bond &bond)
    {
      bonds.state[bond.index] = BondFamilies<dim>::broken;
      broken_here.push_back({bond.particle, bond.index});
    }

    /** Break every intact bond whose stretch exceeds @p limit. */
    void
    break_above_stretch(const double limit)
    {
      for_each_intact([&](const Bond &bond) {
        if (bond.extension() > limit * bond.reference.length)
          break_bond(bond);
      });
    }

    /** Bonds broken through this view. */
    std::size_t
    n_broken() const
    {
      return broken_here.size();
    }

    /** The bonds broken through this view, in the order of the breaks. */
    const std::vector<StoredBond> &
    broken_bonds() const
    {
      return broken_here;
    }

    /** The bond families, read only (for models that split the energy into bonds). */
    const BondFamilies<dim> &
    families() const
    {
      return bonds;
    }

    /** The displacements the extensions are of. */
    ArrayView<const Tensor<1, dim>>
    displacements() const
    {
      return displacement;
    }

  private:
    BondFamilies<dim>              &bonds;
    ArrayView<const Tensor<1, dim>> displacement;
    std::vector<StoredBond>         broken_here;
  };
} // namespace PeriArlequin

#endif

#ifndef periarlequin_fe_mapping_without_similarity_h
#define periarlequin_fe_mapping_without_similarity_h

#include <deal.II/fe/mapping_q.h>

#include <memory>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The bilinear (trilinear) mapping, evaluated afresh on every cell. deal.II's FEValues
   * reuse the Jacobians of the previous cell when the next one is a translation of it, but
   * only when the program runs on one thread: on a box mesh the weights JxW of most cells then
   * differ in the last bit between one thread and several, and with them the FE zone's mass,
   * stiffness and loads. Through this mapping the FE zone computes every cell's geometry the
   * same way whatever the thread count (DEAL_II_NUM_THREADS), so its results do not depend on
   * it. The cost is a Jacobian per quadrature point where a translated cell could have copied
   * it, on one thread only and only where FEValues are used: assembly (set-up, growths) and
   * the strain checks, not the time step's K u.
   */
  template <int dim>
  class MappingWithoutSimilarity : public MappingQ<dim>
  {
  public:
    MappingWithoutSimilarity()
      : MappingQ<dim>(1)
    {}

    std::unique_ptr<Mapping<dim>>
    clone() const override
    {
      return std::make_unique<MappingWithoutSimilarity<dim>>(*this);
    }

  protected:
    CellSimilarity::Similarity
    fill_fe_values(
      const typename Triangulation<dim>::cell_iterator &cell,
      const CellSimilarity::Similarity /*similarity*/,
      const Quadrature<dim>                                          &quadrature,
      const typename Mapping<dim>::InternalDataBase                  &internal_data,
      internal::FEValuesImplementation::MappingRelatedData<dim, dim> &output_data) const override
    {
      return MappingQ<dim>::fill_fe_values(cell,
                                           CellSimilarity::none,
                                           quadrature,
                                           internal_data,
                                           output_data);
    }
  };
} // namespace PeriArlequin

#endif

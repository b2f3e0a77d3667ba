// The cost of a tape and the electrodes it wears (essi/cost.hpp).
#include "essi/cost.hpp"

namespace essi {
namespace {

constexpr double kSecondsPerHour = 3600;
constexpr double kMmPerM = 1000;
constexpr double kMm3PerM3 = 1e9;

}  // namespace

Cost reckon_cost(const Costs& costs, const std::optional<Material>& material, const std::optional<PlateSize>& plate,
                 const CostBasis& basis) {
    Cost c;
    c.currency = costs.currency;
    c.time_s = basis.time_s;
    c.machine_time = basis.machine_time;
    c.machine = costs.machine_per_hour * basis.time_s / kSecondsPerHour;
    c.pierces = costs.per_pierce * static_cast<double>(basis.pierces);
    c.cut = costs.per_m_cut * basis.cut_length_mm / kMmPerM;
    c.total = c.machine + c.pierces + c.cut;
    if (material && plate) {
        c.material_kg = plate->x_mm * plate->y_mm * material->thickness_mm / kMm3PerM3 * material->density_kg_m3;
        c.material = costs.material_per_kg * *c.material_kg;
        c.total += *c.material;
    }
    return c;
}

ConsumableUse consumable_use(const ElectrodeLife& life, unsigned long long pierces, double arc_on_s) {
    ConsumableUse u;
    u.pierces = pierces;
    u.arc_on_s = arc_on_s;
    if (life.pierces) u.electrodes += static_cast<double>(pierces) / *life.pierces;
    if (life.arc_s) u.electrodes += arc_on_s / *life.arc_s;
    return u;
}

}  // namespace essi

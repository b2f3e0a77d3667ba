// What a tape costs and how much of an electrode it wears (docs/semantics.md §9, "Cost" and "Consumables"), from
// its statistics and the profile's `costs`, `material`, `plate_mm` and `consumables`.
#pragma once

#include <optional>
#include <string>

#include "essi/profile.hpp"

namespace essi {

// The cost of a tape, term by term, in the profile's currency.
struct Cost {
    std::string currency;
    double time_s = 0;                  // the time the machine is paid for: machine_time_s, else estimated_time_s
    bool machine_time = false;          // time_s is the machine time
    double machine = 0;                 // machine_per_hour × time_s / 3600
    double pierces = 0;                 // per_pierce × pierces
    double cut = 0;                     // per_m_cut × cut_length_mm / 1000
    std::optional<double> material_kg;  // the plate's mass: x · y · thickness · density (needs plate_mm and material)
    std::optional<double> material;     // material_per_kg × material_kg
    double total = 0;                   // the terms that are known
};

// What the tape wears of an electrode: pierces / electrode_pierces + arc_on_s / electrode_arc_s (a life the
// profile does not give takes no part).
struct ConsumableUse {
    double electrodes = 0;
    unsigned long long pierces = 0;  // each torch's
    double arc_on_s = 0;  // each torch's time with its arc on: cutting motions, pierces, dwells while cutting
};
template <>
struct WireFloats<ConsumableUse> : std::true_type {};

// The inputs the cost is reckoned from (the statistics').
struct CostBasis {
    double time_s = 0;
    bool machine_time = false;
    unsigned long long pierces = 0;
    double cut_length_mm = 0;
};

[[nodiscard]] Cost reckon_cost(const Costs& costs, const std::optional<Material>& material,
                               const std::optional<PlateSize>& plate, const CostBasis& basis);
[[nodiscard]] ConsumableUse consumable_use(const ElectrodeLife& life, unsigned long long pierces, double arc_on_s);

}  // namespace essi

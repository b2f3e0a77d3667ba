// Statistics as bytes (essi/stats.hpp: save_stats, restore_stats).
#include "essi/stats.hpp"

namespace essi {

namespace {

template <class T>
void put_optional(WireWriter& out, const std::optional<T>& v) {
    out.put(v.has_value());
    if (v) out.put(*v);
}

template <class T>
bool get_optional(WireReader& in, std::optional<T>& v) {
    bool has = false;
    if (!in.get(has)) return false;
    if (!has) {
        v.reset();
        return true;
    }
    return in.get(v.emplace());
}

void save_cost(WireWriter& out, const Cost& c) {
    out.put_string(c.currency);
    out.put_all(c.time_s, c.machine_time, c.machine, c.pierces, c.cut);
    put_optional(out, c.material_kg);
    put_optional(out, c.material);
    out.put(c.total);
}

bool restore_cost(WireReader& in, Cost& c) {
    return in.get_string(c.currency) && in.get_all(c.time_s, c.machine_time, c.machine, c.pierces, c.cut) &&
           get_optional(in, c.material_kg) && get_optional(in, c.material) && in.get(c.total);
}

}  // namespace

void save_stats(WireWriter& out, const Stats& s) {
    for (const double v : {s.cut_length_mm, s.cut_length_compensated_mm, s.mark_length_mm, s.travel_length_mm,
                           s.rapid_length_mm, s.estimated_time_s})
        out.put(v);
    for (const unsigned long long v : {s.pierces, s.blocks, s.motions}) out.put(v);
    for (const Box* b : {&s.cut_bbox, &s.motion_bbox, &s.machine_cut_bbox, &s.machine_motion_bbox}) b->save(out);
    out.put(s.end_position);
    put_optional(out, s.machine_time);
    put_optional(out, s.consumables);
    out.put(s.cost.has_value());
    if (s.cost) save_cost(out, *s.cost);
}

bool restore_stats(WireReader& in, Stats& s) {
    for (double* v : {&s.cut_length_mm, &s.cut_length_compensated_mm, &s.mark_length_mm, &s.travel_length_mm,
                      &s.rapid_length_mm, &s.estimated_time_s})
        if (!in.get(*v)) return false;
    for (unsigned long long* v : {&s.pierces, &s.blocks, &s.motions})
        if (!in.get(*v)) return false;
    for (Box* b : {&s.cut_bbox, &s.motion_bbox, &s.machine_cut_bbox, &s.machine_motion_bbox})
        if (!b->restore(in)) return false;
    bool has_cost = false;
    if (!in.get(s.end_position) || !get_optional(in, s.machine_time) || !get_optional(in, s.consumables) ||
        !in.get(has_cost))
        return false;
    if (!has_cost) {
        s.cost.reset();
        return true;
    }
    return restore_cost(in, s.cost.emplace());
}

}  // namespace essi

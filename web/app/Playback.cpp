#include "app/Playback.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "app/Document.hpp"
#include "essi/stats.hpp"

namespace essi::viewer {

MotionTimes::MotionTimes(std::vector<float> seconds) : seconds_(std::move(seconds)) {
    before_.reserve(seconds_.size() / kStride + 1);
    double t = 0;
    for (std::size_t i = 0; i < seconds_.size(); ++i) {
        if (i % kStride == 0) before_.push_back(t);
        t += seconds_[i];
    }
    before_.push_back(t);  // (past the last stride: the sum)
}

double MotionTimes::before(std::size_t motion) const {
    const std::size_t k = std::min(motion / kStride, before_.size() - 1);
    double t = before_[k];
    for (std::size_t i = k * kStride; i < motion && i < seconds_.size(); ++i) t += seconds_[i];
    return t;
}

void Playback::toggle(std::size_t n) {
    if (!active || position >= static_cast<double>(n)) position = 0;
    active = true;
    playing = !playing;
}

void Playback::step_forward(std::size_t n) {
    active = true;
    playing = false;
    position = std::min(static_cast<double>(n), std::floor(position) + 1);
}

void Playback::step_back() {
    active = true;
    playing = false;
    position = std::max(0.0, std::ceil(position) - 1);
}

void Playback::rewind() {
    active = true;
    position = 0;
}

void Playback::show_all(std::size_t n) {
    active = false;
    playing = false;
    position = static_cast<double>(n);
}

void Playback::seek(double motion) {
    active = true;
    position = motion;
}

void Playback::stop() {
    playing = false;
    active = false;
}

void Playback::advance(float seconds, const MotionTimes& times) {
    if (!playing) return;
    const std::size_t n = times.size();
    double budget = static_cast<double>(seconds) * std::clamp(factor, kMinFactor, kMaxFactor);
    while (position < static_cast<double>(n)) {
        const auto i = static_cast<std::size_t>(position);
        const double d = times.seconds(i);
        const double left = (1 - (position - std::floor(position))) * d;
        if (d > 0 && budget < left) {
            position += budget / d;
            return;
        }
        budget -= left;
        position = static_cast<double>(i + 1);
    }
    position = static_cast<double>(n);
    playing = false;
}

double Playback::elapsed_s(const Document& doc, const MotionTimesSource& source) const {
    const double total = total_s(doc);
    const std::size_t n = doc.motions.size();
    const MotionTimes* times = active && position < static_cast<double>(n) ? source.motion_times() : nullptr;
    if (!times || times->size() != n) return total;
    const auto i = static_cast<std::size_t>(position);
    const double t = times->before(i) + (position - std::floor(position)) * times->seconds(i);
    return std::min(t, total);
}

double Playback::total_s(const Document& doc) { return statistics_time_s(doc.stats); }

std::size_t Playback::limit(std::size_t n) const {
    if (!active) return n;
    return std::min(n, static_cast<std::size_t>(std::ceil(position)));
}

Playback::At Playback::at(std::size_t n) const {
    const auto whole = static_cast<std::size_t>(position);
    const std::size_t motion = std::min(whole, n - 1);
    return {motion, whole >= n ? 1.0 : position - std::floor(position)};
}

}  // namespace essi::viewer

#include "app/Playback.hpp"

#include <algorithm>
#include <cmath>

#include "app/Document.hpp"

namespace essi::viewer {

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
    time_before_.clear();
}

void Playback::advance(float seconds, const Document& doc) {
    if (!playing) return;
    const std::size_t n = doc.motions.size();
    double budget = static_cast<double>(seconds) * std::clamp(factor, kMinFactor, kMaxFactor);
    while (position < static_cast<double>(n)) {
        const auto i = static_cast<std::size_t>(position);
        const double d = doc.duration_s(i);
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

void Playback::make_times(const Document& doc) const {
    const std::size_t n = doc.motions.size();
    time_before_.assign(1, 0.0);
    double t = 0;
    for (std::size_t i = 0; i < n; ++i) {
        t += doc.duration_s(i);
        if ((i + 1) % kTimeStride == 0) time_before_.push_back(t);
    }
    time_before_.push_back(t);  // (the total)
}

double Playback::elapsed_s(const Document& doc) const {
    if (time_before_.empty()) make_times(doc);
    const std::size_t n = doc.motions.size();
    if (position >= static_cast<double>(n)) return time_before_.back();
    const auto i = static_cast<std::size_t>(position);
    double t = time_before_[i / kTimeStride];
    for (std::size_t k = i / kTimeStride * kTimeStride; k < i; ++k) t += doc.duration_s(k);
    return t + (position - std::floor(position)) * doc.duration_s(i);
}

double Playback::total_s(const Document& doc) const {
    if (time_before_.empty()) make_times(doc);
    return time_before_.back();
}

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

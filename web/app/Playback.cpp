#include "app/Playback.hpp"

#include <algorithm>
#include <cmath>

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
}

void Playback::advance(float seconds, std::size_t n) {
    if (!playing) return;
    position += speed * seconds;
    if (position >= static_cast<double>(n)) {
        position = static_cast<double>(n);
        playing = false;
    }
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

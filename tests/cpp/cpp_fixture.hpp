// SPDX-License-Identifier: MIT
// The C++ wrapper suite's shared helpers: a ground, stepping by seconds, and whether a
// call throws the wrapper's error with a given status and message.
#pragma once

#include <impulse2d/impulse2d.hpp>

#include <cmath>
#include <string>

namespace cpp_fixture {

/// A static 40 m x 2 m box whose top is at y = 0.
inline impulse2d::Shape make_ground(impulse2d::World& world) {
    impulse2d::Body ground = world.create_body(impulse2d::body_def(I2D_BODY_STATIC, {0.0f, -1.0f}));
    return ground.create_box(20.0f, 1.0f);
}

/// Steps of 1/60 s with 4 substeps making up `seconds`.
inline void step_seconds(impulse2d::World& world, float seconds) {
    const int steps = static_cast<int>(std::lround(seconds * 60.0f));
    for (int i = 0; i < steps; ++i) {
        world.step(1.0f / 60.0f, 4);
    }
}

/// Whether fn throws impulse2d::Error with status and a message containing text.
template <class F>
bool throws(F fn, i2d_status status, const char* text) {
    try {
        fn();
    } catch (const impulse2d::Error& e) {
        return e.status() == status && std::string(e.what()).find(text) != std::string::npos;
    }
    return false;
}

}  // namespace cpp_fixture

// SPDX-License-Identifier: MIT
// The fuzzer's calls of the runtime API (issue 40): a body's, a shape's and the world's
// settings after creation, contact and sensor data, distances. Included by fuzz_api.cpp
// inside its namespace, after its helpers (pick_*, check_body_finite, fail).

i2d_polygon fuzz_polygon(FuzzInput& in) {
    i2d_polygon p = i2d_make_box(in.small_real(), in.small_real());
    if (in.byte() > 200) {
        p.count = static_cast<int32_t>(in.u32());  // any count a C caller could store
    }
    if (in.byte() > 200) {
        p.vertices[in.byte() % I2D_MAX_POLYGON_VERTICES] = in.vec2();
    }
    p.radius = in.flag() ? 0.0f : in.real();
    return p;
}

void run_body_setting_call(FuzzInput& in, uint8_t op) {
    const i2d_body_id b = pick_body(in);
    switch (op % 11) {
        case 0: i2d_body_set_mass_data(b, i2d_mass_data{in.real(), in.vec2(), in.real()}); break;
        case 1: i2d_body_apply_mass_from_shapes(b); break;
        case 2: {
            const i2d_rot q = in.flag() ? i2d_make_rot(in.real()) : i2d_rot{in.real(), in.real()};
            i2d_body_set_target_transform(b, i2d_transform{in.vec2(), q}, in.real());
            break;
        }
        case 3: i2d_body_set_bullet(b, in.flag()); break;
        case 4: i2d_body_enable_sleep(b, in.flag()); break;
        case 5: i2d_body_set_sleep_threshold(b, in.real()); break;
        case 6: i2d_body_set_gravity_scale(b, in.real()); break;
        case 7: i2d_body_set_linear_damping(b, in.real()); break;
        case 8: i2d_body_set_angular_damping(b, in.real()); break;
        case 9: i2d_body_set_fixed_rotation(b, in.flag()); break;
        default: {
            // Out of the world and back, whatever the program does to it meanwhile: a
            // change or, as often, the no-op of asking for what it is.
            const bool enable = in.flag() != i2d_body_is_enabled(b);
            const i2d_status status = enable ? i2d_body_enable(b) : i2d_body_disable(b);
            if (status == I2D_OK && (i2d_body_is_enabled(b) != enable || (!enable && i2d_body_is_awake(b)))) {
                fail("a body is not as enabling or disabling left it", double(enable), 0);
            }
            break;
        }
    }
    const i2d_mass_data m = i2d_body_get_mass_data(b);
    if (!(std::isfinite(m.mass) && std::isfinite(m.rotational_inertia) && std::isfinite(m.center.x) &&
          std::isfinite(m.center.y))) {
        fail("non-finite mass data", m.mass, m.rotational_inertia);
    }
    check_body_finite(b);
}

void run_shape_setting_call(FuzzInput& in, uint8_t op) {
    const i2d_shape_id s = pick_shape(in);
    const bool null_geometry = in.byte() > 245;
    switch (op % 9) {
        case 0: {
            const i2d_circle c{in.small_vec2(), in.flag() ? in.small_real() : in.real()};
            i2d_shape_set_circle(s, null_geometry ? nullptr : &c);
            break;
        }
        case 1: {
            const i2d_capsule c{in.small_vec2(), in.small_vec2(), in.small_real()};
            i2d_shape_set_capsule(s, null_geometry ? nullptr : &c);
            break;
        }
        case 2: {
            const i2d_segment g{in.small_vec2(), in.flag() ? in.small_vec2() : in.vec2()};
            i2d_shape_set_segment(s, null_geometry ? nullptr : &g);
            break;
        }
        case 3: {
            const i2d_polygon p = fuzz_polygon(in);
            i2d_shape_set_polygon(s, null_geometry ? nullptr : &p);
            break;
        }
        case 4: i2d_shape_set_density(s, in.real(), in.flag()); break;
        case 5: i2d_shape_set_material(s, i2d_surface_material{in.real(), in.real(), in.real(), in.real()}); break;
        case 6: i2d_shape_enable_sensor_events(s, in.flag()); break;
        case 7: i2d_shape_enable_contact_events(s, in.flag()); break;
        default: i2d_shape_enable_hit_events(s, in.flag()); break;
    }
    i2d_shape_get_material(s);
    i2d_shape_are_sensor_events_enabled(s);
    i2d_shape_are_contact_events_enabled(s);
    i2d_shape_are_hit_events_enabled(s);
    check_body_finite(i2d_shape_get_body(s));
}

// Contact and sensor data into a buffer of any capacity, maybe NULL; every value read
// back is finite.
void run_contact_data_call(FuzzInput& in, uint8_t op) {
    i2d_contact_data contacts[4];
    i2d_shape_id visitors[4];
    const int32_t capacity = in.flag() ? in.count(4) : static_cast<int32_t>(in.u32());
    const bool null_out = in.byte() > 230;
    const int32_t room = capacity > 4 && !null_out ? 4 : capacity;
    int32_t filled = 0;
    switch (op % 3) {
        case 0: filled = i2d_body_get_contact_data(pick_body(in), null_out ? nullptr : contacts, room); break;
        case 1: filled = i2d_shape_get_contact_data(pick_shape(in), null_out ? nullptr : contacts, room); break;
        default: i2d_shape_get_sensor_overlaps(pick_shape(in), null_out ? nullptr : visitors, room); return;
    }
    for (int32_t k = 0; k < filled && k < room && k < 4 && !null_out; ++k) {
        const i2d_manifold& m = contacts[k].manifold;
        for (int32_t p = 0; p < m.point_count && p < 2; ++p) {
            if (!finite2(m.points[p].point) || !std::isfinite(contacts[k].normal_impulses[p])) {
                fail("non-finite contact data", m.points[p].point.x, contacts[k].normal_impulses[p]);
            }
        }
    }
}

void run_distance_call(FuzzInput& in, uint8_t op) {
    if (op % 2 == 0) {
        const i2d_vec2 p = i2d_shape_get_closest_point(pick_shape(in), in.vec2());
        if (!finite2(p)) {
            fail("non-finite closest point", p.x, p.y);
        }
        return;
    }
    i2d_vec2 points[2][8];
    for (auto& list : points) {
        for (auto& p : list) {
            p = in.small_vec2();
        }
    }
    const i2d_shape_proxy a = i2d_make_proxy(points[0], 1 + in.byte() % 8, in.small_real());
    const i2d_shape_proxy b = i2d_make_proxy(points[1], 1 + in.byte() % 8, in.small_real());
    const i2d_rot qa = in.flag() ? i2d_make_rot(in.real()) : i2d_rot{in.real(), in.real()};
    const i2d_distance_result d = i2d_shape_distance(in.byte() > 245 ? nullptr : &a, i2d_transform{in.vec2(), qa},
                                                     &b, i2d_transform{in.small_vec2(), i2d_make_rot(in.real())});
    if (!(std::isfinite(d.distance) && d.distance >= 0.0f)) {
        fail("distance not finite and non-negative", d.distance, 0);
    }
}

void run_world_setting_call(FuzzInput& in, uint8_t op) {
    const i2d_world_id w = pick_world(in);
    switch (op % 9) {
        case 8: i2d_world_shift_origin(w, in.flag() ? in.small_vec2() : in.vec2()); break;
        case 0: i2d_world_enable_sleeping(w, in.flag()); break;
        case 1: i2d_world_enable_continuous(w, in.flag()); break;
        case 2: i2d_world_set_contact_tuning(w, in.real(), in.real(), in.real()); break;
        case 3: i2d_world_set_joint_tuning(w, in.real(), in.real()); break;
        case 4: i2d_world_set_restitution_threshold(w, in.real()); break;
        case 5: i2d_world_set_hit_event_threshold(w, in.real()); break;
        case 6: i2d_world_set_user_data(w, in.flag() ? g_held : nullptr); break;
        default: {
            // The settings read back create a world like it (or are refused, for a bad id);
            // the impact chains turn over (no input read: the corpus keeps its meaning).
            const i2d_world_def def = i2d_world_get_settings(w);
            const i2d_world_id twin = i2d_world_create(&def);
            i2d_world_destroy(twin);
            i2d_world_enable_impact_chains(w, !def.enable_impact_chains);
            break;
        }
    }
    i2d_world_get_user_data(w);
}

void run_runtime_call(FuzzInput& in, uint8_t op) {
    switch (op % 5) {
        case 0: run_body_setting_call(in, in.byte()); break;
        case 1: run_shape_setting_call(in, in.byte()); break;
        case 2: run_world_setting_call(in, in.byte()); break;
        case 3: run_contact_data_call(in, in.byte()); break;
        default: run_distance_call(in, in.byte()); break;
    }
}

// SPDX-License-Identifier: MIT
// The fuzzer's calls of the character mover (issue 39): casts and collides of hostile
// capsules, the plane solver and clipper on plane arrays of any count (negative, NULL with
// a count, thousands), defs of any values and cookie, and moves with any input, inside a
// query callback too. Finite in, finite out: every accepted answer is finite, a cast's
// fraction is in [0, 1], a plane's normal unit, a clip no longer than what it clipped, and
// a refused move leaves its result zeroed. Included by fuzz_api.cpp inside its namespace,
// after fuzz_runtime_calls.inl (it uses pick_world, query_filter, fail, finite2,
// check_unit_normal and check_all_finite).

// Plane arrays of up to this many live in the harness's own buffer; larger ones are made
// on the heap, so that a count is never longer than the array behind it.
constexpr int32_t fuzz_plane_room = 16;
constexpr int32_t fuzz_many_planes = 1000;

i2d_capsule fuzz_capsule(FuzzInput& in) {
    if (in.flag()) {
        return i2d_capsule{in.small_vec2(), in.small_vec2(), in.small_real()};
    }
    return i2d_capsule{in.vec2(), in.vec2(), in.real()};
}

// A plane: mostly a unit normal at a fuzzed angle with a small offset, sometimes anything.
i2d_collision_plane fuzz_plane(FuzzInput& in) {
    i2d_collision_plane p{};
    if (in.byte() < 200) {
        const i2d_rot q = i2d_make_rot(in.small_real());
        p.plane.normal = i2d_vec2{q.c, q.s};
        p.plane.offset = in.small_real();
        p.push_limit = in.flag() ? FLT_MAX : in.small_real();
    } else {
        p.plane.normal = in.vec2();
        p.plane.offset = in.real();
        p.push_limit = in.real();
    }
    p.push = in.real();  // an output: whatever the caller left there
    p.clip_velocity = in.flag();
    return p;
}

// Fills planes (room for fuzz_plane_room) or `many` with fuzzed planes and returns the
// array and count to pass: a few, none, thousands, a negative count, or NULL with a count.
i2d_collision_plane* fuzz_planes(FuzzInput& in, i2d_collision_plane* planes, std::vector<i2d_collision_plane>& many,
                                 int32_t* count) {
    switch (in.byte() % 8) {
        case 0:
            *count = -static_cast<int32_t>(1 + in.byte());
            return planes;
        case 1:
            *count = 1 + in.byte() % 4;
            return nullptr;
        case 2: {
            many.resize(static_cast<size_t>(fuzz_many_planes));
            for (auto& p : many) {
                p = fuzz_plane(in);
            }
            *count = fuzz_many_planes;
            return many.data();
        }
        default: {
            *count = in.byte() % (fuzz_plane_room + 1);
            for (int32_t i = 0; i < *count; ++i) {
                planes[i] = fuzz_plane(in);
            }
            return planes;
        }
    }
}

i2d_character_def fuzz_character_def(FuzzInput& in) {
    i2d_character_def def = i2d_default_character_def();
    const uint8_t which = in.byte();
    if (which & 1) def.max_slope_angle = in.flag() ? in.small_real() : in.real();
    if (which & 2) def.step_height = in.small_real();
    if (which & 4) def.snap_distance = in.small_real();
    if (which & 8) def.skin = in.flag() ? in.small_real() : in.real();
    if (which & 16) def.max_iterations = static_cast<int32_t>(in.flag() ? in.byte() % 70 : in.u32());
    if (which & 32) def.push_mass = in.flag() ? 100.0f * in.small_real() : in.real();
    if (which & 64) def.filter = query_filter(in);
    if (in.byte() > 240) def.internal_cookie = in.u32();  // uninitialised, as a C caller may leave it
    return def;
}

void check_character_result(const i2d_character_result& r, i2d_status status) {
    if (status != I2D_OK) {
        static const i2d_character_result zero{};
        if (std::memcmp(&r, &zero, sizeof r) != 0) {
            fail("a refused move left its result unzeroed", r.position.x, r.position.y);
        }
        return;
    }
    if (!finite2(r.position) || !finite2(r.velocity) || !finite2(r.ground_normal) || !finite2(r.ground_velocity)) {
        fail("a move gave a non-finite result", r.position.x, r.velocity.x);
    }
    if (r.on_ground) {
        check_unit_normal(r.ground_normal, "a move's ground normal is not unit");
    }
    if (r.hit_count < 0 || r.hit_count > 64) {
        fail("a move counted hits out of range", r.hit_count, 0);
    }
}

struct MoverCallbackContext {
    FuzzInput* in;
    i2d_world_id world;
};

// Inside a query the world is locked: a move that pushes (valid otherwise) must be refused.
bool move_inside_query(i2d_shape_id, void* context) {
    auto& c = *static_cast<MoverCallbackContext*>(context);
    FuzzInput& in = *c.in;
    i2d_character_def def = i2d_default_character_def();
    def.push_mass = in.flag() ? 0.0f : 80.0f;
    const i2d_capsule capsule{{0.0f, 0.3f}, {0.0f, 1.5f}, 0.3f};
    const i2d_vec2 position = in.small_vec2();
    const i2d_vec2 velocity = in.small_vec2();
    i2d_character_result r;
    const i2d_status status = i2d_world_move_character(c.world, &def, &capsule, position, velocity, 1.0f / 60.0f, &r);
    if (def.push_mass > 0.0f && status == I2D_OK) {
        fail("a pushing move was accepted inside a query callback", def.push_mass, 0);
    }
    check_character_result(r, status);
    return in.byte() < 128;
}

void run_mover_call(FuzzInput& in, uint8_t sub) {
    const i2d_world_id w = pick_world(in);
    switch (sub % 6) {
        case 0: {
            const i2d_capsule mover = fuzz_capsule(in);
            const i2d_vec2 translation = in.flag() ? in.small_vec2() : in.vec2();
            const bool null_mover = in.byte() >= 245;
            const i2d_query_filter filter = query_filter(in);
            const float f = i2d_world_cast_mover(w, null_mover ? nullptr : &mover, translation, filter);
            check_cast_length(translation, i2d_last_status());
            if (!(f >= 0.0f && f <= 1.0f)) {
                fail("a mover cast's fraction is outside [0, 1]", f, 0);
            }
            break;
        }
        case 1: {
            const i2d_capsule mover = fuzz_capsule(in);
            i2d_collision_plane out[fuzz_plane_room];
            const int32_t capacity = in.flag() ? in.count(fuzz_plane_room) : static_cast<int32_t>(in.u32());
            const bool null_out = in.byte() > 230;
            const int32_t room = capacity > fuzz_plane_room && !null_out ? fuzz_plane_room : capacity;
            const i2d_query_filter filter = query_filter(in);
            const int32_t total = i2d_world_collide_mover(w, &mover, filter, null_out ? nullptr : out, room);
            if (total < 0) {
                fail("a collide counted below zero", total, 0);
            }
            for (int32_t i = 0; i < total && i < room && i < fuzz_plane_room && !null_out; ++i) {
                if (!finite2(out[i].plane.normal) || !std::isfinite(out[i].plane.offset)) {
                    fail("a collide gave a non-finite plane", out[i].plane.normal.x, out[i].plane.offset);
                }
                check_unit_normal(out[i].plane.normal, "a collide's plane normal is not unit");
            }
            break;
        }
        case 2: {
            i2d_collision_plane planes[fuzz_plane_room];
            std::vector<i2d_collision_plane> many;
            int32_t count = 0;
            i2d_collision_plane* array = fuzz_planes(in, planes, many, &count);
            const i2d_vec2 delta = in.flag() ? in.small_vec2() : in.vec2();
            const i2d_plane_result r = i2d_solve_planes(delta, array, count);
            if (!finite2(r.translation) || r.iteration_count < 0 || r.iteration_count > 32) {
                fail("solve_planes gave a non-finite translation or a bad count", r.translation.x, r.iteration_count);
            }
            for (int32_t i = 0; i < count && i2d_last_status() == I2D_OK; ++i) {
                if (!(std::isfinite(array[i].push) && array[i].push >= 0.0f)) {
                    fail("solve_planes gave a push that is not finite and >= 0", array[i].push, i);
                }
            }
            break;
        }
        case 3: {
            i2d_collision_plane planes[fuzz_plane_room];
            std::vector<i2d_collision_plane> many;
            int32_t count = 0;
            i2d_collision_plane* array = fuzz_planes(in, planes, many, &count);
            const i2d_vec2 v = in.flag() ? in.small_vec2() : in.vec2();
            const i2d_vec2 clipped = i2d_clip_vector(v, array, count);
            if (!finite2(clipped)) {
                fail("clip_vector gave a non-finite vector", clipped.x, clipped.y);
            }
            const double before = std::hypot(double(v.x), double(v.y)), after = std::hypot(double(clipped.x), double(clipped.y));
            if (i2d_last_status() == I2D_OK && after > before * (1.0 + 1e-5) + 1e-30) {
                fail("clip_vector lengthened the vector", before, after);
            }
            break;
        }
        case 4: {
            MoverCallbackContext context{&in, w};
            i2d_world_overlap_aabb(w, i2d_aabb{in.small_vec2(), in.small_vec2()}, i2d_default_query_filter(),
                                   move_inside_query, &context);
            break;
        }
        default: {
            const i2d_character_def def = fuzz_character_def(in);
            const i2d_capsule capsule = fuzz_capsule(in);
            const i2d_vec2 position = in.flag() ? in.small_vec2() : in.vec2();
            const i2d_vec2 velocity = in.flag() ? i2d_vec2{8.0f * in.small_real(), 8.0f * in.small_real()} : in.vec2();
            const float time_step = in.flag() ? 1.0f / 60.0f : in.real();
            i2d_character_result r;
            std::memset(&r, 0xAB, sizeof r);
            const bool null_def = in.byte() > 245, null_capsule = in.byte() > 245, null_out = in.byte() > 250;
            const i2d_status status = i2d_world_move_character(w, null_def ? nullptr : &def,
                                                               null_capsule ? nullptr : &capsule, position, velocity,
                                                               time_step, null_out ? nullptr : &r);
            if (null_out && status == I2D_OK) {
                fail("a move without a result was accepted", 0, 0);
            }
            if (!null_out) {
                check_character_result(r, status);
            }
            check_all_finite();
            break;
        }
    }
}

// SPDX-License-Identifier: MIT
// The fuzzer's calls of the debug draw (issue 39): i2d_world_draw with a def built from
// the input (any flags, any bounds, callbacks left NULL at random, sometimes no def or an
// uninitialised one). Its callbacks check that every float they get is finite and now
// and then call back in: every change to the drawn world must be refused as locked,
// reads and nested draws answered. A draw changes nothing: the world's state hash is the
// same after it; a def the API must refuse is refused, with no callback called. Included
// by fuzz_api.cpp inside its namespace, after its helpers (pick_*, fail, finite2).

// What the callbacks share: the program, the world drawn and how deep draws are nested.
struct DrawProbe {
    FuzzInput* in;
    i2d_world_id world;
    int calls;
    int depth;
};

constexpr int max_draw_depth = 2;  // a callback's own draw with callbacks, and no deeper

void check_finite(float v, const char* what) {
    if (!std::isfinite(v)) {
        fail(what, v, 0.0);
    }
}

void check_finite(i2d_vec2 p, const char* what) {
    if (!finite2(p)) {
        fail(what, p.x, p.y);
    }
}

void check_finite(i2d_transform xf, const char* what) {
    check_finite(xf.p, what);
    if (!std::isfinite(xf.q.c) || !std::isfinite(xf.q.s)) {
        fail(what, xf.q.c, xf.q.s);
    }
}

i2d_debug_draw fuzz_draw_def(FuzzInput& in, DrawProbe& probe, uint8_t variant);

// A call that changes the drawn world, from inside its draw: refused as locked.
void expect_locked(i2d_status status, const char* what) {
    if (status != I2D_ERR_WORLD_LOCKED) {
        fail(what, double(status), 0.0);
    }
}

// Now and then (as the input says), a call back into the library from a callback.
void poke_while_drawing(DrawProbe& probe) {
    FuzzInput& in = *probe.in;
    ++probe.calls;
    if (in.byte() < 192) {
        return;
    }
    const i2d_world_id w = probe.world;
    switch (in.byte() % 8) {
        case 0: expect_locked(i2d_world_step(w, 1.0f / 60.0f, 4), "a step inside a draw was not refused"); break;
        case 1: expect_locked(i2d_world_destroy(w), "destroying the world inside its draw was not refused"); break;
        case 2: {
            const i2d_body_def def = i2d_default_body_def();
            const bool created = !I2D_IS_NULL(i2d_body_create(w, &def));
            if (created || i2d_last_status() != I2D_ERR_WORLD_LOCKED) {
                fail("a body was created inside a draw", double(i2d_last_status()), 0.0);
            }
            break;
        }
        case 3: {  // a held body of the drawn world
            const i2d_body_id b = pick_body(in);
            const bool ours = i2d_body_is_valid(b) && i2d_body_get_world(b).bits == w.bits;
            const i2d_status status = i2d_body_set_linear_velocity(b, in.vec2());
            if (ours) {
                expect_locked(status, "a body of the drawn world was changed inside the draw");
            }
            break;
        }
        case 4:
            i2d_world_get_counters(w);
            if (i2d_last_status() != I2D_OK) {
                fail("a getter was refused inside a draw", double(i2d_last_status()), 0.0);
            }
            break;
        case 5: {
            i2d_shape_id out[4];
            if (i2d_world_overlap_aabb_ids(w, i2d_aabb{in.vec2(), in.vec2()}, i2d_default_query_filter(), out, 4) < 0 &&
                i2d_last_status() == I2D_ERR_WORLD_LOCKED) {
                fail("a query was refused as locked inside a draw", 0.0, 0.0);
            }
            break;
        }
        case 6:
            if (probe.depth < max_draw_depth) {
                ++probe.depth;
                const i2d_debug_draw nested = fuzz_draw_def(in, probe, in.byte());
                const i2d_status status = i2d_world_draw(w, &nested);
                --probe.depth;
                if (status == I2D_ERR_WORLD_LOCKED) {
                    fail("a draw inside a draw was refused as locked", 0.0, 0.0);
                }
            }
            break;
        default: expect_locked(i2d_world_set_gravity(w, in.small_vec2()), "gravity set inside a draw"); break;
    }
}

DrawProbe& probe_of(void* context) { return *static_cast<DrawProbe*>(context); }

void fuzz_draw_polygon(const i2d_vec2* vertices, int32_t count, i2d_color, void* context) {
    if (vertices == nullptr || count != 4) {  // only boxes are drawn as outlines
        fail("an outline was not a box", double(count), 0.0);
    }
    for (int32_t i = 0; i < count; ++i) {
        check_finite(vertices[i], "a non-finite outline vertex");
    }
    poke_while_drawing(probe_of(context));
}

void fuzz_draw_solid_polygon(i2d_transform xf, const i2d_vec2* vertices, int32_t count, float radius, i2d_color,
                             void* context) {
    check_finite(xf, "a polygon placed by a non-finite transform");
    if (vertices == nullptr || count < 3 || count > I2D_MAX_POLYGON_VERTICES) {
        fail("a polygon with a bad vertex count", double(count), 0.0);
    }
    for (int32_t i = 0; i < count; ++i) {
        check_finite(vertices[i], "a non-finite polygon vertex");
    }
    check_finite(radius, "a non-finite polygon radius");
    poke_while_drawing(probe_of(context));
}

void fuzz_draw_circle(i2d_vec2 center, float radius, i2d_color, void* context) {
    check_finite(center, "a non-finite circle centre");
    check_finite(radius, "a non-finite circle radius");
    poke_while_drawing(probe_of(context));
}

void fuzz_draw_solid_circle(i2d_transform xf, float radius, i2d_color, void* context) {
    check_finite(xf, "a non-finite solid circle");
    check_finite(radius, "a non-finite solid circle radius");
    poke_while_drawing(probe_of(context));
}

void fuzz_draw_solid_capsule(i2d_vec2 p1, i2d_vec2 p2, float radius, i2d_color, void* context) {
    check_finite(p1, "a non-finite capsule end");
    check_finite(p2, "a non-finite capsule end");
    check_finite(radius, "a non-finite capsule radius");
    poke_while_drawing(probe_of(context));
}

void fuzz_draw_segment(i2d_vec2 p1, i2d_vec2 p2, i2d_color, void* context) {
    check_finite(p1, "a non-finite segment end");
    check_finite(p2, "a non-finite segment end");
    poke_while_drawing(probe_of(context));
}

void fuzz_draw_transform(i2d_transform xf, void* context) {
    check_finite(xf, "a non-finite frame");
    poke_while_drawing(probe_of(context));
}

void fuzz_draw_point(i2d_vec2 p, float size, i2d_color, void* context) {
    check_finite(p, "a non-finite point");
    check_finite(size, "a non-finite point size");
    poke_while_drawing(probe_of(context));
}

void fuzz_draw_string(i2d_vec2 p, const char* text, i2d_color, void* context) {
    check_finite(p, "a non-finite text position");
    if (text == nullptr || std::strlen(text) > 64) {
        fail("a text that is missing or runs on", 0.0, 0.0);
    }
    poke_while_drawing(probe_of(context));
}

// The def: every callback set or NULL by a bit of the input, every flag too. Variants 0
// and 1 turn every flag on; 9 culls to a box around a held body; the rest take flags and
// bounds from the input, hostile values included.
i2d_debug_draw fuzz_draw_def(FuzzInput& in, DrawProbe& probe, uint8_t variant) {
    i2d_debug_draw d = i2d_default_debug_draw();
    const uint32_t set = uint32_t(in.byte()) | uint32_t(in.byte()) << 8;
    d.draw_polygon = (set & 1u) ? fuzz_draw_polygon : nullptr;
    d.draw_solid_polygon = (set & 2u) ? fuzz_draw_solid_polygon : nullptr;
    d.draw_circle = (set & 4u) ? fuzz_draw_circle : nullptr;
    d.draw_solid_circle = (set & 8u) ? fuzz_draw_solid_circle : nullptr;
    d.draw_solid_capsule = (set & 16u) ? fuzz_draw_solid_capsule : nullptr;
    d.draw_segment = (set & 32u) ? fuzz_draw_segment : nullptr;
    d.draw_transform = (set & 64u) ? fuzz_draw_transform : nullptr;
    d.draw_point = (set & 128u) ? fuzz_draw_point : nullptr;
    d.draw_string = (set & 256u) ? fuzz_draw_string : nullptr;
    const bool all = variant < 2;
    const uint32_t flags = all ? ~0u : uint32_t(in.byte()) | uint32_t(in.byte()) << 8;
    d.draw_shapes = (flags & 1u) != 0;
    d.draw_joints = (flags & 2u) != 0;
    d.draw_joint_extras = (flags & 4u) != 0;
    d.draw_bounds = (flags & 8u) != 0;
    d.draw_mass = (flags & 16u) != 0;
    d.draw_contacts = (flags & 32u) != 0;
    d.draw_contact_normals = (flags & 64u) != 0;
    d.draw_contact_impulses = (flags & 128u) != 0;
    d.draw_friction_impulses = (flags & 256u) != 0;
    d.draw_graph_colors = (flags & 512u) != 0;
    d.draw_islands = (flags & 1024u) != 0;
    if (variant == 9 && g_held->body_count > 0) {
        const i2d_vec2 at = i2d_body_get_position(g_held->bodies[in.byte() % g_held->body_count]);
        const float half = std::fabs(in.small_real());
        d.use_drawing_bounds = true;
        d.drawing_bounds = i2d_aabb{{at.x - half, at.y - half}, {at.x + half, at.y + half}};
    } else if (!all) {
        d.use_drawing_bounds = in.flag();
        d.drawing_bounds = in.flag() ? i2d_aabb{in.vec2(), in.vec2()} : i2d_aabb{in.small_vec2(), in.small_vec2()};
    }
    if (in.byte() > 245) {
        d.internal_cookie = in.u32();  // an uninitialised def
    }
    d.context = &probe;
    return d;
}

// Whether the API must refuse the def: uninitialised, or bounds used that are not a box.
bool draw_def_is_bad(const i2d_debug_draw& d) {
    const i2d_debug_draw good = i2d_default_debug_draw();
    if (d.internal_cookie != good.internal_cookie) {
        return true;
    }
    const i2d_aabb& b = d.drawing_bounds;
    return d.use_drawing_bounds &&
           !(finite2(b.min) && finite2(b.max) && b.min.x <= b.max.x && b.min.y <= b.max.y);
}

void run_draw_call(FuzzInput& in, uint8_t sub) {
    const uint8_t variant = static_cast<uint8_t>(sub - 24);
    DrawProbe probe{&in, pick_world(in), 0, 0};
    const i2d_debug_draw d = fuzz_draw_def(in, probe, variant);
    const bool valid_world = i2d_world_is_valid(probe.world);
    const uint64_t hash = valid_world ? i2d_world_get_state_hash(probe.world) : 0;
    const i2d_status status = i2d_world_draw(probe.world, variant == 8 ? nullptr : &d);
    if (status == I2D_OK && (variant == 8 || draw_def_is_bad(d) || !valid_world)) {
        fail("a draw the API must refuse was accepted", double(variant), 0.0);
    }
    if (status != I2D_OK && probe.calls > 0) {
        fail("a refused draw called its callbacks", double(status), double(probe.calls));
    }
    if (valid_world && i2d_world_get_state_hash(probe.world) != hash) {
        fail("a draw changed the world", 0.0, 0.0);
    }
}

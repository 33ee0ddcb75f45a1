// SPDX-License-Identifier: MIT
// The fuzzer's calls of the contact hooks and explosions (issue 39). The hooks answer by
// a seed the program chose, from their arguments alone (they run on the step's workers),
// check that what they are handed is finite and that a call on their world from inside
// is refused as locked. Included by fuzz_api.cpp inside its namespace, after its helpers.

// What the hooks read while a step runs: written only between steps.
struct HookSeeds {
    uint64_t filter = 0;
    uint64_t pre_solve = 0;
};
HookSeeds g_hook_seeds;

// One bit of the seed's mix with the pair.
bool seeded_answer(uint64_t seed, i2d_shape_id a, i2d_shape_id b) {
    uint64_t z = seed ^ (a.bits * 0x9E3779B97F4A7C15ull) ^ b.bits;
    z = (z ^ (z >> 31)) * 0xBF58476D1CE4E5B9ull;
    return ((z ^ (z >> 29)) & 1) != 0;
}

// Inside a hook every call on the world is refused, getters too.
void check_locked_inside_hook(i2d_shape_id shape) {
    i2d_shape_get_aabb(shape);
    if (i2d_last_status() != I2D_ERR_WORLD_LOCKED) {
        fail("a getter inside a contact hook was not refused as locked", double(i2d_last_status()), 0);
    }
}

bool fuzz_custom_filter(i2d_shape_id a, i2d_shape_id b, void* context) {
    const HookSeeds& seeds = *static_cast<const HookSeeds*>(context);
    check_locked_inside_hook(a);
    return seeded_answer(seeds.filter, a, b);
}

bool fuzz_pre_solve(i2d_shape_id a, i2d_shape_id b, const i2d_manifold* m, void* context) {
    const HookSeeds& seeds = *static_cast<const HookSeeds*>(context);
    check_locked_inside_hook(b);
    if (m->point_count < 1 || m->point_count > 2 || !std::isfinite(m->normal.x) || !std::isfinite(m->normal.y)) {
        fail("a pre-solve hook was handed a bad manifold", double(m->point_count), double(m->normal.x));
    }
    for (int32_t i = 0; i < m->point_count; ++i) {
        const i2d_manifold_point& p = m->points[i];
        if (!std::isfinite(p.point.x) || !std::isfinite(p.point.y) || !std::isfinite(p.penetration)) {
            fail("a pre-solve hook was handed a non-finite point", double(p.point.x), double(p.penetration));
        }
    }
    return seeded_answer(seeds.pre_solve, a, b);
}

i2d_explosion_def fuzz_explosion(FuzzInput& in) {
    i2d_explosion_def def = i2d_default_explosion_def();
    def.mask_bits = in.flag() ? def.mask_bits : in.u64();
    def.position = in.vec2();
    def.radius = in.flag() ? in.small_real() : in.real();
    def.falloff = in.flag() ? 0.0f : in.real();
    def.impulse_per_length = in.real();
    return def;
}

void run_hook_call(FuzzInput& in, uint8_t sub) {
    switch (sub % 5) {
        case 0:
            i2d_world_set_custom_filter_callback(pick_world(in), in.flag() ? fuzz_custom_filter : nullptr,
                                                 &g_hook_seeds);
            break;
        case 1:
            i2d_world_set_pre_solve_callback(pick_world(in), in.flag() ? fuzz_pre_solve : nullptr, &g_hook_seeds);
            break;
        case 2: {
            const i2d_shape_id shape = pick_shape(in);
            const bool flag = in.flag();
            if (i2d_shape_enable_pre_solve_events(shape, flag) == I2D_OK &&
                i2d_shape_are_pre_solve_events_enabled(shape) != flag) {
                fail("a shape's pre-solve opt-in did not read back", double(flag), 0);
            }
            break;
        }
        case 3: {
            const i2d_explosion_def def = fuzz_explosion(in);
            i2d_world_explode(pick_world(in), in.byte() < 250 ? &def : nullptr);
            break;
        }
        default:
            g_hook_seeds.filter = in.u64();
            g_hook_seeds.pre_solve = in.u64();
            break;
    }
}

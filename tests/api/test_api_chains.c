/* SPDX-License-Identifier: MIT */
/* Chains through the C API: creation, ids, segments, destruction with the chain or the
 * body, and every refused input leaving the world as it was. */
#include <impulse2d/impulse2d.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

static const i2d_vec2 k_floor[6] = {{6, 0}, {4, 0}, {2, 0}, {0, 0}, {-2, 0}, {-4, 0}};

static i2d_chain_def floor_def(void) {
    i2d_chain_def def = i2d_default_chain_def();
    def.points = k_floor;
    def.count = 6;
    return def;
}

static void expect_refused(i2d_body_id body, const i2d_chain_def* def, i2d_status expected, const char* what) {
    i2d_world_id world = i2d_body_get_world(body);
    const i2d_world_counters before = i2d_world_get_counters(world);
    i2d_chain_id chain = i2d_chain_create(body, def);
    const i2d_status status = i2d_last_status();
    char message[256];
    snprintf(message, sizeof message, "%s", i2d_last_error_message());
    const i2d_world_counters after = i2d_world_get_counters(world);
    if (!I2D_IS_NULL(chain) || status != expected || after.shape_count != before.shape_count || message[0] == 0) {
        ++i2d_check_failures;
        fprintf(stderr, "%s:%d: %s: status %s (\"%s\"), expected %s; shapes %d -> %d\n", __FILE__, __LINE__, what,
                i2d_status_string(status), message, i2d_status_string(expected), (int)before.shape_count,
                (int)after.shape_count);
    }
}

I2D_TEST(api_chain_create_and_destroy) {
    i2d_world_def wd = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&wd);
    i2d_body_def bd = i2d_default_body_def();
    i2d_body_id ground = i2d_body_create(world, &bd);
    i2d_chain_def def = floor_def();
    i2d_chain_id chain = i2d_chain_create(ground, &def);
    I2D_REQUIRE(!I2D_IS_NULL(chain));
    I2D_CHECK(i2d_chain_is_valid(chain));
    /* 6 points, open: 3 segments between points 1..4. */
    i2d_shape_id segments[4];
    I2D_CHECK(i2d_chain_get_segments(chain, segments, 4) == 3);
    I2D_CHECK(i2d_world_get_counters(world).shape_count == 3);
    I2D_CHECK(i2d_shape_get_type(segments[0]) == I2D_SHAPE_CHAIN_SEGMENT);
    I2D_CHECK(I2D_ID_EQUALS(i2d_shape_get_chain(segments[2]), chain));
    I2D_CHECK(I2D_ID_EQUALS(i2d_shape_get_body(segments[1]), ground));
    /* A segment is destroyed with its chain, never alone. */
    I2D_CHECK_STATUS(i2d_shape_destroy(segments[0]), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK(i2d_shape_is_valid(segments[0]));
    /* The body cannot turn dynamic while it holds a chain. */
    I2D_CHECK_STATUS(i2d_body_set_type(ground, I2D_BODY_DYNAMIC), I2D_ERR_INVALID_ARGUMENT);
    I2D_CHECK_STATUS(i2d_body_set_type(ground, I2D_BODY_KINEMATIC), I2D_OK);
    I2D_CHECK_STATUS(i2d_body_set_type(ground, I2D_BODY_STATIC), I2D_OK);
    I2D_CHECK_STATUS(i2d_chain_destroy(chain), I2D_OK);
    I2D_CHECK(!i2d_chain_is_valid(chain));
    I2D_CHECK(!i2d_shape_is_valid(segments[1]));
    I2D_CHECK(i2d_world_get_counters(world).shape_count == 0);
    /* Stale and wrong-kind ids. */
    I2D_CHECK_STATUS(i2d_chain_destroy(chain), I2D_ERR_INVALID_HANDLE);
    I2D_CHECK(i2d_chain_get_segments(chain, NULL, 0) == -1);
    i2d_chain_id not_a_chain = {ground.bits};
    I2D_CHECK(!i2d_chain_is_valid(not_a_chain));
    I2D_CHECK(!i2d_chain_is_valid(I2D_NULL_CHAIN_ID));
    /* Destroying the body destroys its chains. */
    chain = i2d_chain_create(ground, &def);
    I2D_REQUIRE(!I2D_IS_NULL(chain));
    i2d_body_destroy(ground);
    I2D_CHECK(!i2d_chain_is_valid(chain));
    I2D_CHECK(i2d_world_get_counters(world).shape_count == 0);
    /* And destroying the world. */
    ground = i2d_body_create(world, &bd);
    chain = i2d_chain_create(ground, &def);
    i2d_world_destroy(world);
    I2D_CHECK(!i2d_chain_is_valid(chain));
    I2D_CHECK_STATUS(i2d_chain_destroy(chain), I2D_ERR_INVALID_HANDLE);
}

static i2d_chain_id g_created;

static bool create_inside(i2d_shape_id shape, void* context) {
    i2d_chain_def def = floor_def();
    (void)shape;
    g_created = i2d_chain_create(*(i2d_body_id*)context, &def);
    return false;
}

I2D_TEST(api_chain_refuses_bad_input) {
    i2d_world_def wd = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&wd);
    i2d_body_def bd = i2d_default_body_def();
    i2d_body_id ground = i2d_body_create(world, &bd);
    i2d_shape_def sd = i2d_default_shape_def();
    i2d_shape_create_box(ground, &sd, 1.0f, 1.0f);
    const uint64_t hash = i2d_world_get_state_hash(world);

    i2d_chain_def def = floor_def();
    expect_refused(ground, NULL, I2D_ERR_INVALID_ARGUMENT, "NULL def");
    i2d_chain_def zeroed;
    memset(&zeroed, 0, sizeof zeroed);
    zeroed.points = k_floor;
    zeroed.count = 6;
    expect_refused(ground, &zeroed, I2D_ERR_INVALID_ARGUMENT, "def not from i2d_default_chain_def");
    def.points = NULL;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "NULL points");
    def = floor_def();
    def.count = 3;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "3 points open (2 of them ghosts)");
    def.count = 2;
    def.is_loop = true;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "2 points looped");
    def = floor_def();
    def.count = -1;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "negative count");
    const i2d_vec2 with_nan[5] = {{3, 0}, {2, 0}, {NAN, 0}, {0, 0}, {-1, 0}};
    def = floor_def();
    def.points = with_nan;
    def.count = 5;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "a NaN point");
    const i2d_vec2 with_inf[5] = {{3, 0}, {2, 0}, {1, INFINITY}, {0, 0}, {-1, 0}};
    def.points = with_inf;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "an infinite point");
    const i2d_vec2 far_away[5] = {{3, 0}, {2, 0}, {1, 2e9f}, {0, 0}, {-1, 0}};
    def.points = far_away;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "a point beyond 1e9 m");
    const i2d_vec2 repeated[5] = {{3, 0}, {2, 0}, {1, 0}, {1.001f, 0}, {-1, 0}};
    def.points = repeated;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "a zero-length segment");
    const i2d_vec2 closing[3] = {{0, 0}, {1, 0}, {0.001f, 0}};
    def.points = closing;
    def.count = 3;
    def.is_loop = true;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "a loop whose closing segment has no length");
    /* Materials: a count that is neither 0, 1 nor the segment count, NULL, NaN. */
    i2d_surface_material m[3] = {{0.5f, 0.0f, 0.0f, 0.0f}, {0.5f, 0.0f, 0.0f, 0.0f}, {0.5f, 0.0f, 0.0f, 0.0f}};
    def = floor_def();
    def.materials = m;
    def.material_count = 2;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "2 materials for 3 segments");
    def.materials = NULL;
    def.material_count = 3;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "NULL materials");
    m[1].friction = NAN;
    def.materials = m;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "NaN friction");
    m[1].friction = 0.5f;
    m[2].restitution = -1.0f;
    expect_refused(ground, &def, I2D_ERR_INVALID_ARGUMENT, "negative restitution");
    m[2].restitution = 0.0f;
    /* A dynamic body, a stale body. */
    i2d_body_def dyn = i2d_default_body_def();
    dyn.type = I2D_BODY_DYNAMIC;
    i2d_body_id dynamic = i2d_body_create(world, &dyn);
    def = floor_def();
    expect_refused(dynamic, &def, I2D_ERR_INVALID_ARGUMENT, "a dynamic body");
    i2d_body_destroy(dynamic);
    I2D_CHECK(I2D_IS_NULL(i2d_chain_create(dynamic, &def)) && i2d_last_status() == I2D_ERR_INVALID_HANDLE);
    /* From inside a query callback: the world is locked. */
    i2d_aabb everywhere = {{-10, -10}, {10, 10}};
    g_created = I2D_NULL_CHAIN_ID;
    I2D_CHECK_STATUS(i2d_world_overlap_aabb(world, everywhere, i2d_default_query_filter(), create_inside, &ground),
                     I2D_OK);
    I2D_CHECK(I2D_IS_NULL(g_created));
    /* Nothing changed; and the good def still works, with 3 materials. */
    I2D_CHECK(i2d_world_get_state_hash(world) == hash);
    I2D_CHECK(i2d_world_get_counters(world).shape_count == 1);
    def.materials = m;
    def.material_count = 3;
    I2D_CHECK(!I2D_IS_NULL(i2d_chain_create(ground, &def)));
    i2d_world_destroy(world);
}

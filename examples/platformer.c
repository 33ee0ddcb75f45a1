/* SPDX-License-Identifier: MIT */
/* The README's platformer: a character moved by game code with i2d_world_move_character
 * walks onto a ledge, jumps up through a one-way platform and lands on it, then rides a
 * moving platform, while boxes use the same one-way platform through the pre-solve hook. */
#include <impulse2d/impulse2d.h>
#include <stdio.h>

#define DT (1.0f / 60.0f)
#define GRAVITY 10.0f
#define WALK_SPEED 4.0f
#define JUMP_SPEED 8.0f
#define ONE_WAY 2u             /* the one-way platforms' category */
#define ONE_WAY_TOP 2.2f
#define LEDGE_TOP 0.2f

typedef struct character {
    i2d_vec2 position;         /* of its feet */
    float fall_speed;          /* m/s, up positive */
    bool on_ground;
    i2d_vec2 ground_velocity;
    i2d_shape_id ground;
} character;

static i2d_shape_id add_box(i2d_world_id world, i2d_body_type type, float x, float y, float hw, float hh,
                            const i2d_shape_def* def) {
    i2d_body_def body = i2d_default_body_def();
    body.type = type;
    body.position = (i2d_vec2){x, y};
    return i2d_shape_create_box(i2d_body_create(world, &body), def, hw, hh);
}

/* Boxes: a one-way platform acts only when it pushes the other shape up. */
static bool one_way(i2d_shape_id a, i2d_shape_id b, const i2d_manifold* m, void* context) {
    const i2d_shape_id* platform = context;
    const float sign = a.bits == platform->bits ? 1.0f : b.bits == platform->bits ? -1.0f : 0.0f;
    return sign * m->normal.y > 0.95f;   /* the normal points from A to B */
}

/* One frame of game code: walk, jump, fall, and move the capsule. The mover is a query,
 * not a contact: the character leaves one-way platforms out of what it meets while it
 * rises or its feet are below their top. */
static void move(i2d_world_id world, character* c, float walk, bool jump) {
    static const i2d_capsule capsule = {{0.0f, 0.3f}, {0.0f, 1.2f}, 0.3f};   /* feet at the origin */
    i2d_character_def def = i2d_default_character_def();
    c->fall_speed = c->on_ground ? (jump ? JUMP_SPEED : 0.0f) : c->fall_speed - GRAVITY * DT;
    if (c->fall_speed > 0.0f || c->position.y < ONE_WAY_TOP) {
        def.filter.mask_bits &= ~(uint64_t)ONE_WAY;    /* up through one-way platforms */
    }
    const i2d_vec2 velocity = {walk + c->ground_velocity.x, c->fall_speed + c->ground_velocity.y};
    i2d_character_result r;
    i2d_world_move_character(world, &def, &capsule, c->position, velocity, DT, &r);
    c->position = r.position;
    c->fall_speed = r.velocity.y - c->ground_velocity.y;
    c->on_ground = r.on_ground;
    c->ground_velocity = r.ground_velocity;              /* ride what it stands on */
    c->ground = r.ground_shape;
}

int main(void) {
    i2d_world_def world_def = i2d_default_world_def();
    i2d_world_id world = i2d_world_create(&world_def);
    i2d_shape_def solid = i2d_default_shape_def();
    add_box(world, I2D_BODY_STATIC, 10.0f, -0.5f, 20.0f, 0.5f, &solid);               /* ground, top at 0 */
    add_box(world, I2D_BODY_STATIC, 3.0f, LEDGE_TOP - 0.5f, 3.0f, 0.5f, &solid);      /* a ledge, x 0..6 */
    i2d_shape_def one_way_def = i2d_default_shape_def();
    one_way_def.filter.category_bits = ONE_WAY;
    one_way_def.enable_pre_solve_events = true;
    i2d_shape_id platform = add_box(world, I2D_BODY_STATIC, 9.5f, ONE_WAY_TOP - 0.1f, 1.5f, 0.1f, &one_way_def);
    i2d_world_set_pre_solve_callback(world, one_way, &platform);
    i2d_shape_id crate = add_box(world, I2D_BODY_DYNAMIC, 8.3f, 0.25f, 0.25f, 0.25f, &solid);
    i2d_body_set_linear_velocity(i2d_shape_get_body(crate), (i2d_vec2){0.0f, 9.0f});  /* up through it */
    i2d_shape_id ferry = add_box(world, I2D_BODY_KINEMATIC, 15.5f, 0.1f, 1.0f, 0.1f, &solid);  /* top at 0.2 */

    character c = {{-4.0f, 0.0f}, 0.0f, true, {0.0f, 0.0f}, {0}};
    int frame = 0;
    for (; frame < 600 && c.position.x < 2.0f; ++frame) {            /* onto the ledge */
        move(world, &c, WALK_SPEED, false);
        i2d_world_step(world, DT, 4);
    }
    printf("on the ledge: feet at %.2f m\n", c.position.y);
    for (; frame < 1200 && c.position.x < 9.0f; ++frame) {           /* off it, under the platform */
        move(world, &c, WALK_SPEED, false);
        i2d_world_step(world, DT, 4);
    }
    move(world, &c, 0.0f, true);                                     /* jump straight up */
    for (int k = 0; k < 120; ++k, ++frame) {
        i2d_world_step(world, DT, 4);
        move(world, &c, 0.0f, false);
    }
    printf("on the one-way platform: feet at %.2f m, beside the crate at %.2f m\n", c.position.y,
           i2d_body_get_position(i2d_shape_get_body(crate)).y);
    for (; frame < 2400 && c.ground.bits != ferry.bits; ++frame) {   /* off it, onto the ferry */
        move(world, &c, c.position.x < 15.0f ? WALK_SPEED : 0.0f, false);
        i2d_world_step(world, DT, 4);
    }
    i2d_body_set_linear_velocity(i2d_shape_get_body(ferry), (i2d_vec2){1.0f, 0.0f});  /* it sets off */
    const float boarded = c.position.x;
    for (int k = 0; k < 120; ++k, ++frame) {                          /* 2 s standing on it */
        move(world, &c, 0.0f, false);
        i2d_world_step(world, DT, 4);
    }
    printf("rode the ferry %.2f m in 2 s\n", c.position.x - boarded);
    i2d_world_destroy(world);
    return 0;
}

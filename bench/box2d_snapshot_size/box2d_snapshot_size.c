/* SPDX-License-Identifier: MIT */
/* Box2D v3's snapshot size on the benchmark scenes, for the size table of issue 38.
 *
 * Built by run.sh against a Box2D v3 checkout (never part of impulse2d's build): the scenes are
 * Box2D's own benchmark builders (shared/benchmarks.c, the ones the side-by-side tool times),
 * stepped as its benchmark app steps them (the scene's step function, then b2World_Step at
 * 1/60 s with 4 substeps, 1 worker, continuous on) to the same step as impulse2d_snapshot_bench
 * measures, and then b2World_Snapshot's size is printed with the counts beside it: dynamic bodies
 * (every shape's body found by an overlap query over the whole world) and touching contact
 * points (b2Body_GetContactData, each contact counted once). The snapshot is also saved and
 * restored into a new world, whose state hash must equal the saved world's.
 *
 * usage: box2d_snapshot_size [scene=steps ...]   (default: large_pyramid=120 rain=400
 *        joint_grid=120 many_pyramids=120); prints CSV:
 *        scene,steps,dynamic_bodies,touching_pairs,touching_points,snapshot_bytes */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "benchmarks.h"
#include "box2d/box2d.h"

typedef void create_fn(b2WorldId worldId);
typedef float step_fn(b2WorldId worldId, int stepCount);

typedef struct scene {
    const char* name;
    create_fn* create;
    step_fn* step;
    int steps; /* impulse2d_snapshot_bench's moment for the scene */
} scene;

static const scene scenes[] = {
    {"large_pyramid", CreateLargePyramid, NULL, 120},
    {"rain", CreateRain, StepRain, 400},
    {"joint_grid", CreateJointGrid, NULL, 120},
    {"many_pyramids", CreateManyPyramids, NULL, 120},
};
#define SCENE_COUNT ((int)(sizeof scenes / sizeof scenes[0]))

typedef struct census {
    b2BodyId* bodies; /* each body once, found through its shapes */
    int count;
    int capacity;
    unsigned char* seen; /* by body index1 */
    int seen_capacity;
    int failed;
} census;

static bool visit_shape(b2ShapeId shapeId, void* context) {
    census* c = context;
    b2BodyId body = b2Shape_GetBody(shapeId);
    if (body.index1 >= c->seen_capacity) {
        int capacity = 2 * body.index1 + 1024;
        unsigned char* seen = realloc(c->seen, (size_t)capacity);
        if (seen == NULL) {
            c->failed = 1;
            return false;
        }
        memset(seen + c->seen_capacity, 0, (size_t)(capacity - c->seen_capacity));
        c->seen = seen;
        c->seen_capacity = capacity;
    }
    if (c->seen[body.index1]) {
        return true;
    }
    c->seen[body.index1] = 1;
    if (c->count == c->capacity) {
        int capacity = 2 * c->capacity + 1024;
        b2BodyId* bodies = realloc(c->bodies, (size_t)capacity * sizeof *bodies);
        if (bodies == NULL) {
            c->failed = 1;
            return false;
        }
        c->bodies = bodies;
        c->capacity = capacity;
    }
    c->bodies[c->count++] = body;
    return true;
}

static bool same_body(b2BodyId a, b2BodyId b) {
    return a.index1 == b.index1 && a.world0 == b.world0 && a.generation == b.generation;
}

/* Dynamic bodies, touching pairs and their points; false when out of memory. */
static bool count(b2WorldId world, int* bodies, int* pairs, int* points) {
    census c = {0};
    b2AABB everything = {{-1.0e5f, -1.0e5f}, {1.0e5f, 1.0e5f}};
    b2ContactData* data = NULL;
    int capacity = 0;
    *bodies = 0;
    *pairs = 0;
    *points = 0;
    b2World_OverlapAABB(world, b2Pos_zero, everything, b2DefaultQueryFilter(), visit_shape, &c);
    for (int i = 0; i < c.count && !c.failed; ++i) {
        b2BodyId body = c.bodies[i];
        if (b2Body_GetType(body) != b2_dynamicBody) {
            continue;
        }
        *bodies += 1;
        int needed = b2Body_GetContactCapacity(body);
        if (needed > capacity) {
            free(data);
            capacity = 2 * needed;
            data = malloc((size_t)capacity * sizeof *data);
            if (data == NULL) {
                c.failed = 1;
                break;
            }
        }
        int n = b2Body_GetContactData(body, data, capacity);
        for (int k = 0; k < n; ++k) {
            b2BodyId a = b2Shape_GetBody(data[k].shapeIdA);
            b2BodyId b = b2Shape_GetBody(data[k].shapeIdB);
            b2BodyId other = same_body(a, body) ? b : a;
            /* A contact of two dynamic bodies is met from both: count it from body A. */
            if (b2Body_GetType(other) == b2_dynamicBody && !same_body(a, body)) {
                continue;
            }
            *pairs += data[k].manifold.pointCount > 0;
            *points += data[k].manifold.pointCount;
        }
    }
    free(data);
    free(c.bodies);
    free(c.seen);
    return !c.failed;
}

static int run(const scene* s, int steps) {
    b2WorldDef def = b2DefaultWorldDef();
    def.workerCount = 1;
    b2WorldId world = b2CreateWorld(&def);
    s->create(world);
    for (int i = 0; i < steps; ++i) {
        if (s->step != NULL) {
            s->step(world, i);
        }
        b2World_Step(world, 1.0f / 60.0f, 4);
    }
    int bodies, pairs, points;
    if (!count(world, &bodies, &pairs, &points)) {
        fprintf(stderr, "box2d_snapshot_size: out of memory\n");
        return 3;
    }
    int size = b2World_Snapshot(world, NULL, 0);
    uint8_t* image = malloc((size_t)(size > 0 ? size : 1));
    if (size <= 0 || image == NULL || b2World_Snapshot(world, image, size) != size) {
        fprintf(stderr, "box2d_snapshot_size: %s: b2World_Snapshot failed (size %d)\n", s->name, size);
        free(image);
        return 3;
    }
    /* The image is a working snapshot: a world made from it has the same state. */
    b2WorldId copy = b2CreateWorldFromSnapshot(image, size, 1);
    int ok = B2_IS_NON_NULL(copy) && b2World_GetStateHash(copy) == b2World_GetStateHash(world);
    if (B2_IS_NON_NULL(copy)) {
        b2DestroyWorld(copy);
    }
    free(image);
    b2DestroyWorld(world);
    if (!ok) {
        fprintf(stderr, "box2d_snapshot_size: %s: the world made from the snapshot differs\n", s->name);
        return 1;
    }
    printf("%s,%d,%d,%d,%d,%d\n", s->name, steps, bodies, pairs, points, size);
    fflush(stdout);
    return 0;
}

int main(int argc, char** argv) {
    int status = 0;
    b2Version v = b2GetVersion();
    fprintf(stderr, "# Box2D %d.%d.%d, 1 worker, 1/60 s steps with 4 substeps\n", v.major, v.minor, v.revision);
    printf("scene,steps,dynamic_bodies,touching_pairs,touching_points,snapshot_bytes\n");
    if (argc == 1) {
        for (int i = 0; i < SCENE_COUNT; ++i) {
            status |= run(scenes + i, scenes[i].steps);
        }
        return status;
    }
    for (int a = 1; a < argc; ++a) {
        const char* eq = strchr(argv[a], '=');
        int found = 0;
        for (int i = 0; i < SCENE_COUNT; ++i) {
            size_t n = eq ? (size_t)(eq - argv[a]) : strlen(argv[a]);
            if (strlen(scenes[i].name) == n && strncmp(scenes[i].name, argv[a], n) == 0) {
                status |= run(scenes + i, eq ? atoi(eq + 1) : scenes[i].steps);
                found = 1;
            }
        }
        if (!found) {
            fprintf(stderr, "box2d_snapshot_size: no scene '%s' (large_pyramid, rain, joint_grid, many_pyramids)\n",
                    argv[a]);
            status |= 2;
        }
    }
    return status;
}

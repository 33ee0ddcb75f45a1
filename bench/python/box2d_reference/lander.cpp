// SPDX-License-Identifier: MIT
// LunarLander-v3's definitions on Box2D 2.4 (Debian's libbox2d-dev), the engine
// family Gymnasium uses, to compare impulse2d.gym with: compare.py feeds it an episode's
// random draws (terrain heights, initial push, per-frame dispersion, made in Python from
// the seed exactly as impulse2d.gym draws them) and reads one line per frame:
// frame, the 8 observations, reward, terminated. "pilot" flies the PD pilot of
// tests/python/test_gym_lunar_lander.py; "idle" fires nothing.
//
// Build: g++ -O2 -std=c++17 lander.cpp -lbox2d -o lander
#include <box2d/box2d.h>
#include <cmath>
#include <cstdio>
#include <vector>
#include <string>
#include <iostream>
const double S = 30.0, FPS = 50, W = 600 / S, H = 400 / S;
struct Listener : b2ContactListener {
    b2Body* hull; b2Body* legs[2]; bool game_over = false; bool contact[2] = {false, false};
    void BeginContact(b2Contact* c) override {
        b2Body* a = c->GetFixtureA()->GetBody(); b2Body* b = c->GetFixtureB()->GetBody();
        if (a == hull || b == hull) game_over = true;
        for (int i = 0; i < 2; ++i) if (a == legs[i] || b == legs[i]) contact[i] = true;
    }
    void EndContact(b2Contact* c) override {
        b2Body* a = c->GetFixtureA()->GetBody(); b2Body* b = c->GetFixtureB()->GetBody();
        for (int i = 0; i < 2; ++i) if (a == legs[i] || b == legs[i]) contact[i] = false;
    }
};
int pilot(const double* s) {
    double lean = std::fmax(-0.4, std::fmin(0.4, 0.5 * s[0] + 1.0 * s[2]));
    double turn = 0.5 * (lean - s[4]) - 1.0 * s[5];
    double lift = 0.5 * (0.5 * std::fabs(s[0]) - s[1]) - 0.5 * s[3];
    if (s[6] || s[7]) { turn = 0; lift = -0.5 * s[3]; }
    if (lift > std::fabs(turn) && lift > 0.05) return 2;
    if (turn < -0.05) return 3;
    if (turn > 0.05) return 1;
    return 0;
}
int main() {
    std::string mode; std::cin >> mode;
    std::vector<double> xs(11), ys(11); for (int i = 0; i < 11; ++i) { xs[i] = W / 10 * i; std::cin >> ys[i]; }
    double pad; std::cin >> pad; double fx, fy; std::cin >> fx >> fy;
    std::vector<double> disp(2002); for (auto& d : disp) std::cin >> d;
    b2World world(b2Vec2(0, -10));
    Listener L; world.SetContactListener(&L);
    b2BodyDef sd; b2Body* moon = world.CreateBody(&sd);
    b2EdgeShape e; e.SetTwoSided(b2Vec2(0, 0), b2Vec2(W, 0));
    b2FixtureDef fd; fd.shape = &e; moon->CreateFixture(&fd);
    for (int i = 0; i < 10; ++i) { b2EdgeShape s; s.SetTwoSided(b2Vec2(xs[i], ys[i]), b2Vec2(xs[i+1], ys[i+1]));
        b2FixtureDef f; f.shape = &s; f.density = 0; f.friction = 0.1; moon->CreateFixture(&f); }
    b2BodyDef bd; bd.type = b2_dynamicBody; bd.position.Set(W / 2, H);
    b2Body* hull = world.CreateBody(&bd);
    b2Vec2 pts[6] = {{-14, 17}, {-17, 0}, {-17, -10}, {17, -10}, {17, 0}, {14, 17}};
    for (auto& p : pts) p = b2Vec2(p.x / S, p.y / S);
    b2PolygonShape poly; poly.Set(pts, 6);
    b2FixtureDef hf; hf.shape = &poly; hf.density = 5; hf.friction = 0.1; hf.filter.categoryBits = 0x10; hf.filter.maskBits = 1;
    hull->CreateFixture(&hf);
    hull->ApplyForceToCenter(b2Vec2(fx, fy), true);
    L.hull = hull;
    for (int k = 0; k < 2; ++k) { int i = k == 0 ? -1 : 1;
        b2BodyDef ld; ld.type = b2_dynamicBody; ld.position.Set(W / 2 - i * 20 / S, H); ld.angle = i * 0.05;
        b2Body* leg = world.CreateBody(&ld);
        b2PolygonShape box; box.SetAsBox(2 / S, 8 / S);
        b2FixtureDef lf; lf.shape = &box; lf.density = 1; lf.friction = 0.2; lf.filter.categoryBits = 0x20; lf.filter.maskBits = 1;
        leg->CreateFixture(&lf);
        b2RevoluteJointDef j; j.bodyA = hull; j.bodyB = leg; j.localAnchorA.Set(0, 0); j.localAnchorB.Set(i * 20 / S, 18 / S);
        j.enableMotor = true; j.enableLimit = true; j.maxMotorTorque = 40; j.motorSpeed = 0.3 * i;
        if (i == -1) { j.lowerAngle = 0.4; j.upperAngle = 0.9; } else { j.lowerAngle = -0.9; j.upperAngle = -0.4; }
        world.CreateJoint(&j); L.legs[k] = leg; }
    double prev = NAN, total = 0; double s[8] = {0};
    for (int t = 0; t <= 1000; ++t) {
        int a = (t == 0) ? 0 : (mode == "pilot" ? pilot(s) : 0);
        double tipx = std::sin(hull->GetAngle()), tipy = std::cos(hull->GetAngle()), sidex = -tipy, sidey = tipx;
        double d0 = disp[2 * t] / S, d1 = disp[2 * t + 1] / S;
        double m = 0, sp = 0;
        if (a == 2) { m = 1; double ox = tipx * (4 / S + 2 * d0) + sidex * d1, oy = -tipy * (4 / S + 2 * d0) - sidey * d1;
            b2Vec2 p(hull->GetPosition().x + ox, hull->GetPosition().y + oy);
            hull->ApplyLinearImpulse(b2Vec2(-ox * 13 * m, -oy * 13 * m), p, true); }
        if (a == 1 || a == 3) { sp = 1; double dir = a - 2;
            double ox = tipx * d0 + sidex * (3 * d1 + dir * 12 / S), oy = -tipy * d0 - sidey * (3 * d1 + dir * 12 / S);
            b2Vec2 p(hull->GetPosition().x + ox - tipx * 17 / S, hull->GetPosition().y + oy + tipy * 14 / S);
            hull->ApplyLinearImpulse(b2Vec2(-ox * 0.6 * sp, -oy * 0.6 * sp), p, true); }
        world.Step(1.0 / FPS, 6 * 30, 2 * 30);
        b2Vec2 pos = hull->GetPosition(), vel = hull->GetLinearVelocity();
        s[0] = (pos.x - W / 2) / (W / 2); s[1] = (pos.y - (pad + 18 / S)) / (H / 2);
        s[2] = vel.x * (W / 2) / FPS; s[3] = vel.y * (H / 2) / FPS; s[4] = hull->GetAngle();
        s[5] = 20.0 * hull->GetAngularVelocity() / FPS; s[6] = L.contact[0]; s[7] = L.contact[1];
        double sh = -100 * std::sqrt(s[0]*s[0] + s[1]*s[1]) - 100 * std::sqrt(s[2]*s[2] + s[3]*s[3]) - 100 * std::fabs(s[4]) + 10 * s[6] + 10 * s[7];
        double r = std::isnan(prev) ? 0 : sh - prev; prev = sh; r -= m * 0.3 + sp * 0.03;
        bool term = false;
        if (L.game_over || std::fabs(s[0]) >= 1) { term = true; r = -100; }
        if (!hull->IsAwake()) { term = true; r = 100; }
        if (t > 0) total += r;
        printf("%d", t); for (double v : s) printf(" %.6f", v); printf(" %.4f %d\n", r, term);
        if (term && t > 0) break;
    }
    fprintf(stderr, "total %.2f\n", total);
}

# SPDX-License-Identifier: MIT
"""Box2D.b2: Box2D's names without their b2 / b2_ prefix (world, vec2, polygonShape,
fixtureDef, contactListener, rayCastCallback, revoluteJointDef, pi, ...), filled in by
the Box2D package when it is imported."""

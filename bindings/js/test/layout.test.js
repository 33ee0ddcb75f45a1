// SPDX-License-Identifier: MIT
// Struct layouts come from the module's own description (i2d_get_field_infos), and a
// module that does not fit the binding is refused at load, naming every problem.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { i2d } from './fixture.js';
import { Runtime } from '../src/runtime.js';
import { readDescription } from '../src/layout.js';

const headers = new URL('../../../include/impulse2d/', import.meta.url);

/** A deep copy of a description, to doctor. */
function copy(description) {
  return new Map([...description].map(([name, s]) => [name, { ...s, fields: new Map([...s.fields].map(
    ([f, field]) => [f, { ...field }])) }]));
}

/** The message a Runtime over the doctored description is refused with. */
function refusal(description) {
  let message;
  assert.throws(() => new Runtime(i2d.rt.m, description), (error) => {
    message = error.message;
    return /do not match this binding/.test(message);
  });
  return message;
}

test('the module describes every public struct, and the offsets the binding uses are its', () => {
  const description = readDescription(i2d.rt.m);
  const names = new Set();
  for (const file of readdirSync(headers).filter((f) => f.endsWith('.h'))) {
    for (const m of readFileSync(new URL(file, headers), 'utf8').matchAll(/typedef struct (i2d_\w+)/g)) names.add(m[1]);
  }
  assert.ok(names.size >= 30);
  assert.deepEqual([...names].filter((n) => !description.has(n)), []);
  for (const struct of description.values()) assert.ok(struct.fields.size > 0, struct.name);
  // wasm32: pointers are 4 bytes.
  assert.equal(description.get('i2d_field_info').size, 28);
  assert.equal(description.get('i2d_body_def').fields.get('user_data').size, 4);
  assert.equal(i2d.rt.field('i2d_world_def.gravity'), description.get('i2d_world_def').fields.get('gravity').offset);
  assert.equal(i2d.rt.size('i2d_polygon'), description.get('i2d_polygon').size);
  const vertices = description.get('i2d_polygon').fields.get('vertices');
  assert.deepEqual([vertices.kind, vertices.typeName, vertices.count], ['struct', 'i2d_vec2', 8]);
});

test('a module lacking a field the binding uses, or giving it another kind, is refused', () => {
  const description = copy(i2d.rt.description);
  description.get('i2d_body_def').fields.delete('position');
  description.get('i2d_world_def').fields.get('contact_hertz').kind = 'double';
  description.get('i2d_revolute_joint_def').fields.get('enable_motor').kind = 'int32';
  description.delete('i2d_ray_result');
  const message = refusal(description);
  assert.match(message, /i2d_body_def\.position: the module has no such field; this binding uses it as i2d_vec2/);
  assert.match(message, /i2d_world_def\.contact_hertz: the module has double; this binding uses it as float/);
  assert.match(message, /i2d_revolute_joint_def\.enable_motor: the module has int32; this binding uses it as bool/);
  assert.match(message, /i2d_ray_result: not described by the module/);
});

test('vectors must stay two consecutive floats', () => {
  const description = copy(i2d.rt.description);
  const vec2 = description.get('i2d_vec2').fields;
  [vec2.get('x').offset, vec2.get('y').offset] = [4, 0];
  assert.match(refusal(description), /i2d_vec2\.x: offset 4; this binding takes 0/);
});

test('fields and structs the binding does not use are fine', () => {
  const description = copy(i2d.rt.description);
  description.get('i2d_world_def').fields.set('enable_something',
    { name: 'enable_something', kind: 'bool', typeName: 'bool', offset: 58, size: 1, count: 1 });
  description.set('i2d_some_future_struct', { name: 'i2d_some_future_struct', size: 4, align: 4, fields: new Map() });
  const rt = new Runtime(i2d.rt.m, description);
  assert.equal(rt.field('i2d_world_def.enable_something'), 58);
  rt.m._free(rt.allFilter);
  rt.m._free(rt.scratch);
});

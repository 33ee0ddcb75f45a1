/* SPDX-License-Identifier: MIT */
/* Box2D._raycast: b2World.RayCast's loop, compiled. BipedalWalker casts ten rays a frame,
 * each reporting two or three fixtures to Python; through ctypes a cast cost 2.4 us
 * against pybox2d's 1.5, and this C loop (the same semantics as the Python one in
 * _world.py, which remains for a Python without this module) costs about 1 us.
 *
 * The module is not linked to libimpulse2d: bind() takes the address of
 * i2d_world_cast_ray_all from the library that ctypes loaded, so the one library the
 * impulse2d package found serves both. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <impulse2d/impulse2d.h>

#include <stdlib.h>

typedef int32_t cast_ray_all_fn(i2d_world_id world, i2d_vec2 origin, i2d_vec2 translation, i2d_query_filter filter,
                                i2d_ray_result* out, int32_t capacity);

/* Most rays hit a handful of shapes: their results stay on the stack. */
enum { STACK_RESULTS = 32 };

static cast_ray_all_fn* cast_ray_all = NULL;
static PyObject* x_name = NULL;
static PyObject* y_name = NULL;

static PyObject* bind(PyObject* module, PyObject* address) {
    (void)module;
    void* pointer = PyLong_AsVoidPtr(address);
    if (pointer == NULL) {
        if (!PyErr_Occurred()) {
            PyErr_SetString(PyExc_ValueError, "bind: the address of i2d_world_cast_ray_all is NULL");
        }
        return NULL;
    }
    cast_ray_all = (cast_ray_all_fn*)pointer;
    Py_RETURN_NONE;
}

/* A b2Vec2 made as b2Vec2._raw makes it: no __init__, its two slots set. */
static PyObject* new_vec(PyTypeObject* vec_type, float x, float y) {
    PyObject* vec = vec_type->tp_alloc(vec_type, 0);
    if (vec == NULL) {
        return NULL;
    }
    PyObject* px = PyFloat_FromDouble((double)x);
    PyObject* py = PyFloat_FromDouble((double)y);
    const int failed = px == NULL || py == NULL || PyObject_SetAttr(vec, x_name, px) < 0 ||
                       PyObject_SetAttr(vec, y_name, py) < 0;
    Py_XDECREF(px);
    Py_XDECREF(py);
    if (failed) {
        Py_DECREF(vec);
        return NULL;
    }
    return vec;
}

/* Reports the hits nearest first to report(fixture, point, normal, fraction), honouring
 * its answer: -1 ignores the fixture, 0 stops, a fraction clips the ray there, 1 goes on.
 * Returns 0, or -1 with a Python exception set (the callback's, or a bad answer's). */
static int report_hits(const i2d_ray_result* hits, int32_t count, PyObject* fixtures, PyObject* report,
                       PyTypeObject* vec_type) {
    double limit = 1.0;
    for (int32_t i = 0; i < count; ++i) {
        const i2d_ray_result* hit = &hits[i];
        const double fraction = (double)hit->fraction;
        if (fraction > limit) {
            break;
        }
        PyObject* key = PyLong_FromUnsignedLongLong(hit->shape.bits);
        if (key == NULL) {
            return -1;
        }
        PyObject* fixture = PyDict_GetItemWithError(fixtures, key); /* borrowed */
        Py_DECREF(key);
        if (fixture == NULL) {
            if (PyErr_Occurred()) {
                return -1;
            }
            continue; /* a shape the compat world did not make */
        }
        Py_INCREF(fixture); /* the callback may destroy it */
        PyObject* point = new_vec(vec_type, hit->point.x, hit->point.y);
        PyObject* normal = point == NULL ? NULL : new_vec(vec_type, hit->normal.x, hit->normal.y);
        PyObject* at = normal == NULL ? NULL : PyFloat_FromDouble(fraction);
        PyObject* answer = at == NULL ? NULL : PyObject_CallFunctionObjArgs(report, fixture, point, normal, at, NULL);
        Py_DECREF(fixture);
        Py_XDECREF(point);
        Py_XDECREF(normal);
        Py_XDECREF(at);
        if (answer == NULL) {
            return -1;
        }
        const double value = PyFloat_AsDouble(answer);
        Py_DECREF(answer);
        if (value == -1.0 && PyErr_Occurred()) {
            return -1;
        }
        if (value == 0.0) {
            break;
        }
        if (0.0 < value && value < limit) {
            limit = value;
        }
    }
    return 0;
}

static PyObject* ray_cast(PyObject* module, PyObject* args) {
    (void)module;
    unsigned long long world_bits, category_bits, mask_bits;
    double x1, y1, x2, y2;
    PyObject *fixtures, *report, *vec_type;
    if (!PyArg_ParseTuple(args, "KddddKKO!OO!:ray_cast", &world_bits, &x1, &y1, &x2, &y2, &category_bits,
                          &mask_bits, &PyDict_Type, &fixtures, &report, &PyType_Type, &vec_type)) {
        return NULL;
    }
    if (cast_ray_all == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "ray_cast before bind()");
        return NULL;
    }
    const i2d_world_id world = {world_bits};
    /* Rounded to float as ctypes rounds the Python path's doubles. */
    const i2d_vec2 origin = {(float)x1, (float)y1}, translation = {(float)(x2 - x1), (float)(y2 - y1)};
    const i2d_query_filter filter = {category_bits, mask_bits};
    /* Per call, not shared: a callback may cast again before this loop is done. */
    i2d_ray_result on_stack[STACK_RESULTS];
    i2d_ray_result* hits = on_stack;
    int32_t total = cast_ray_all(world, origin, translation, filter, hits, STACK_RESULTS);
    if (total > STACK_RESULTS) {
        hits = (i2d_ray_result*)malloc(sizeof(i2d_ray_result) * (size_t)total);
        if (hits == NULL) {
            return PyErr_NoMemory();
        }
        total = cast_ray_all(world, origin, translation, filter, hits, total);
    }
    int status = total < 0 ? 0 : report_hits(hits, total, fixtures, report, (PyTypeObject*)vec_type);
    if (hits != on_stack) {
        free(hits);
    }
    if (status < 0) {
        return NULL;
    }
    return PyLong_FromLong(total < 0 ? -1 : 0);
}

static PyMethodDef methods[] = {
    {"bind", bind, METH_O, "bind(address): the address of the loaded library's i2d_world_cast_ray_all."},
    {"ray_cast", ray_cast, METH_VARARGS,
     "ray_cast(world, x1, y1, x2, y2, category_bits, mask_bits, fixtures, report, vec_type) -> 0, or -1 when "
     "the library refused the cast."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module_def = {
    PyModuleDef_HEAD_INIT, "_raycast", "b2World.RayCast's loop, compiled.", -1, methods, NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__raycast(void) {
    x_name = PyUnicode_InternFromString("x");
    y_name = PyUnicode_InternFromString("y");
    if (x_name == NULL || y_name == NULL) {
        return NULL;
    }
    return PyModule_Create(&module_def);
}

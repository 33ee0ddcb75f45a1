// SPDX-License-Identifier: MIT
// FunctionRef: a non-owning reference to something callable, for a callback that a
// module is handed for one call instead of holding a reference to another module.
//
// Design note: a template parameter would do where the callee is a template; FunctionRef
// serves where it is not (a function in a .cpp file). It costs an indirect call, so it is
// for paths that run per change (a body woken, a link followed), not per contact per step.
// The callable must outlive the call it is passed to: take it as a parameter, never store it.
#pragma once

#include <type_traits>
#include <utility>

namespace i2d {

template <class Signature>
class FunctionRef;

template <class R, class... Args>
class FunctionRef<R(Args...)> {
public:
    template <class F, class = std::enable_if_t<!std::is_same<std::decay_t<F>, FunctionRef>::value>>
    FunctionRef(F&& f)  // NOLINT(google-explicit-constructor): a lambda passes as it is
        : object_(const_cast<void*>(static_cast<const void*>(&f))), call_(&invoke<std::remove_reference_t<F>>) {}

    R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

private:
    template <class F>
    static R invoke(void* object, Args... args) {
        return (*static_cast<F*>(object))(std::forward<Args>(args)...);
    }

    void* object_;
    R (*call_)(void*, Args...);
};

}  // namespace i2d

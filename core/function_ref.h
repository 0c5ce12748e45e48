// SPDX-License-Identifier: MIT
//
// A non-owning reference to a callable (like C++26's std::function_ref), for
// callbacks on hot paths: unlike std::function it never allocates, so passing
// a lambda that captures a whole shading context costs two pointers.
// The callable must outlive the FunctionRef.
#pragma once

#include <type_traits>
#include <utility>

namespace rt {

template <typename Signature>
class FunctionRef;

template <typename R, typename... Args>
class FunctionRef<R(Args...)> {
public:
    template <typename F, typename = std::enable_if_t<
                              !std::is_same_v<std::decay_t<F>, FunctionRef> &&
                              std::is_invocable_r_v<R, F&, Args...>>>
    FunctionRef(F&& f) noexcept  // NOLINT(google-explicit-constructor): used like a function type
        : object_(const_cast<void*>(static_cast<const void*>(&f))),
          call_([](void* object, Args... args) -> R {
              return (*static_cast<std::remove_reference_t<F>*>(object))(
                  std::forward<Args>(args)...);
          }) {}

    R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

private:
    void* object_;
    R (*call_)(void*, Args...);
};

}  // namespace rt

// SPDX-License-Identifier: MIT
// Steps<Event, Result>: the coroutine generator every algorithm is written as.
//
// An algorithm's body keeps the textbook's shape: it `co_yield`s a fact (an event) wherever a student should see
// one, and `co_return`s its answer. The caller pulls events one at a time with next(); nothing runs before the
// first pull (lazy), and nothing runs after the caller stops pulling. Recursion is a nested generator:
//
//     auto child = cs_clip_3d(i, p2);
//     for (const auto& e : child) co_yield e;     // forward the child's events
//     co_return child.result();                   // and its answer
//
// std::generator would do, but it needs libstdc++ 14; this is the small subset we use, with a result added.
// An exception thrown in the body is rethrown from next() (and from the range-for's ++).
//
// GCC 12 destroys an aggregate temporary in a co_yield expression twice when it has non-trivial members (seen
// with `co_yield PolygonSplit{…, std::move(shared)}`: a use-after-free under ASan; clang is fine). So an event
// that is not trivially destructible must be yielded by name: `const BspEvent e = PolygonSplit{…}; co_yield e;`.
// yield_value refuses the temporary form at compile time; trivially destructible events may be yielded as
// temporaries (a second destruction of those does nothing).
#pragma once

#include <coroutine>
#include <exception>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace hsr::algo {

template <class Event, class Result>
class [[nodiscard]] Steps {
public:
    struct promise_type {
        std::optional<Event> current;     // the event last yielded, held until the next resume
        std::optional<Result> result;     // set by co_return
        std::exception_ptr error;         // set when the body throws

        Steps get_return_object() { return Steps{Handle::from_promise(*this)}; }
        std::suspend_always initial_suspend() noexcept { return {}; }  // lazy: nothing runs before next()
        std::suspend_always final_suspend() noexcept { return {}; }
        std::suspend_always yield_value(const Event& e) {  // a named event, or a child's forwarded one
            current = e;
            return {};
        }
        template <class T>
            requires(!std::is_lvalue_reference_v<T>)
        std::suspend_always yield_value(T&& e) {
            static_assert(std::is_trivially_destructible_v<std::remove_cvref_t<T>>,
                          "yield an event with non-trivial members by name (GCC 12 bug: see the top of steps.h)");
            current.emplace(std::forward<T>(e));
            return {};
        }
        void return_value(Result r) { result = std::move(r); }
        void unhandled_exception() { error = std::current_exception(); }
    };
    using Handle = std::coroutine_handle<promise_type>;

    Steps(Steps&& other) noexcept : handle_(std::exchange(other.handle_, {})) {}
    Steps& operator=(Steps&& other) noexcept {
        if (this != &other) {
            destroy();
            handle_ = std::exchange(other.handle_, {});
        }
        return *this;
    }
    Steps(const Steps&) = delete;
    Steps& operator=(const Steps&) = delete;
    ~Steps() { destroy(); }

    // Runs the body to its next event. Returns the event, or nullptr once the body has returned.
    // The pointer stays valid until the next call.
    const Event* next() {
        if (!handle_ || handle_.done()) return nullptr;
        handle_.promise().current.reset();
        handle_.resume();
        if (auto error = handle_.promise().error) {
            handle_.promise().error = nullptr;
            std::rethrow_exception(error);
        }
        if (handle_.done()) return nullptr;
        return &*handle_.promise().current;
    }

    [[nodiscard]] bool done() const { return !handle_ || handle_.done(); }

    // The co_return'ed answer. Only after the body has returned.
    [[nodiscard]] const Result& result() const& {
        if (!handle_ || !handle_.done() || !handle_.promise().result)
            throw std::logic_error("Steps::result() asked before the algorithm finished");
        return *handle_.promise().result;
    }
    // On a temporary machine the answer is moved out: a reference into it would dangle (C++20 ends a temporary in
    // a range-for's range expression before the loop body runs).
    [[nodiscard]] Result result() && { return std::move(const_cast<Result&>(result())); }

    // Drains the remaining events and returns the answer.
    const Result& run_to_end() & {
        while (next() != nullptr) {
        }
        return result();
    }
    Result run_to_end() && { return std::move(const_cast<Result&>(run_to_end())); }

    // Input range over the remaining events, for `for (const auto& e : steps)`.
    class iterator {
    public:
        using value_type = Event;
        using difference_type = std::ptrdiff_t;
        iterator() = default;
        explicit iterator(Steps* owner) : owner_(owner), event_(owner->next()) {}
        const Event& operator*() const { return *event_; }
        const Event* operator->() const { return event_; }
        iterator& operator++() {
            event_ = owner_->next();
            return *this;
        }
        void operator++(int) { ++*this; }
        bool operator==(std::default_sentinel_t) const { return event_ == nullptr; }

    private:
        Steps* owner_ = nullptr;
        const Event* event_ = nullptr;
    };
    iterator begin() { return iterator{this}; }
    std::default_sentinel_t end() { return {}; }

private:
    explicit Steps(Handle h) : handle_(h) {}
    void destroy() {
        if (handle_) handle_.destroy();
        handle_ = {};
    }
    Handle handle_;
};

}  // namespace hsr::algo

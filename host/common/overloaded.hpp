#pragma once
// One visitor of a std::variant from a lambda per alternative:
// std::visit(Overloaded{[](int) {...}, [](const std::string&) {...}}, value).

namespace meshparticles {

template <typename... Handlers>
struct Overloaded : Handlers... {
  using Handlers::operator()...;
};
template <typename... Handlers>
Overloaded(Handlers...) -> Overloaded<Handlers...>;

}  // namespace meshparticles

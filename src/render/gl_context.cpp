#include "render/gl_context.hpp"

#include <map>
#include <mutex>
#include <stdexcept>

namespace sweep::render {
namespace {

struct Registry {
  std::mutex mutex;
  std::map<std::string, ContextFactory, std::less<>> factories;
};

Registry& registry() {
  static Registry instance;
  return instance;
}

}  // namespace

void register_context_provider(const std::string& name, ContextFactory factory) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  r.factories[name] = std::move(factory);
}

std::unique_ptr<GlContext> create_context(std::string_view name, const ContextRequest& request) {
  ContextFactory factory;
  {
    Registry& r = registry();
    const std::lock_guard lock(r.mutex);
    const auto found = r.factories.find(name);
    if (found == r.factories.end()) {
      std::string known;
      for (const auto& [key, value] : r.factories) known += (known.empty() ? "" : ", ") + key;
      throw std::runtime_error("no GL context provider named '" + std::string(name) +
                               "' (known: " + (known.empty() ? "none" : known) + ")");
    }
    factory = found->second;
  }
  return factory(request);
}

std::vector<std::string> context_provider_names() {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& [key, value] : r.factories) names.push_back(key);
  return names;
}

}  // namespace sweep::render

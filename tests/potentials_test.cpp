// The potential table: every potential has one entry, its name parses back
// to it, and its kernel switch differs from every other's.
#include <gtest/gtest.h>

#include <set>

#include "common/user_error.hpp"
#include "particles/potentials.hpp"

namespace meshparticles::testing {
namespace {

TEST(PotentialTable, EachNameParsesBackToItsPotential) {
  std::set<long long> kernel_defines;
  for (const PotentialSpec& spec : potential_table()) {
    EXPECT_EQ(parse_potential(spec.name), spec.potential);
    EXPECT_EQ(potential_name(spec.potential), spec.name);
    EXPECT_EQ(&potential_spec(spec.potential), &spec);
    EXPECT_TRUE(kernel_defines.insert(spec.kernel_define).second) << spec.name << " shares its kernel switch";
  }
  EXPECT_EQ(potential_names(), (std::vector<std::string>{"exp", "gauss"}));
  EXPECT_EQ(potential_spec(kDefaultPotential).name, "exp");
}

TEST(PotentialTable, AnUnknownNameListsTheChoices) {
  try {
    parse_potential("coulomb");
    FAIL() << "parsed an unknown potential";
  } catch (const UserError& error) {
    EXPECT_STREQ(error.what(), "unknown potential 'coulomb' (choose exp or gauss)");
  }
}

}  // namespace
}  // namespace meshparticles::testing

#pragma once
// A study: every density x test combination of the paper, read from YAML into typed structs.
#include <string>
#include <vector>

namespace pipeline {

struct Density {
  std::string name;    // loose, medium, dense
  double friction = 0; // mu during isotropic compression
};

struct TestCase {
  std::string name;   // test1 ... test5
  std::string scene;  // scene file (absolute path)
};

struct Profile {
  std::string name;
  int lattice = 20;     // lattice sites per axis of the preparation (20 -> 8,000 spheres)
  int max_repeat = 0;   // > 0: each repeat block of a test runs at most this many cycles
};

struct Study {
  std::string file;         // the study YAML
  std::string name;
  std::string output;       // results folder (absolute)
  std::string preparation;  // preparation scene template (absolute); friction set per density
  std::vector<Density> densities;
  std::vector<TestCase> tests;
  std::vector<Profile> profiles;
  const Profile& profile(const std::string& name) const;  // throws naming the known profiles
};

// Reads and validates a study; relative paths are taken from the study file's folder.
Study load_study(const std::string& file);

}  // namespace pipeline

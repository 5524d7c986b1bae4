#pragma once
// The files `dynanav run` writes into OUT. A run into a folder that holds an earlier run's files
// must not leave them beside its own (a trajectory of this run, stats.json of the last one), so
// the run removes every known output before it writes anything. A sink that adds a file adds its
// name to kRunOutputs (run_outputs.cpp).
#include <filesystem>
#include <string>
#include <vector>

namespace dynanav {

/// Names (relative to OUT) of every file a run may write, including temporaries.
const std::vector<std::string>& runOutputNames();

/// Removes the known outputs of an earlier run from `out_dir`; returns how many were there.
/// Other files are left alone. InputError naming the file when one cannot be removed.
int removeEarlierRunOutputs(const std::filesystem::path& out_dir);

}  // namespace dynanav

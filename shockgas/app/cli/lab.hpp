#pragma once
// `shockgas lab [--out DIR]`: the lab's page (docs/gallery.md, "The lab"),
// written into DIR to be opened from there in a browser: file://, no server,
// no network. The page itself is built by cmake/Lab.cmake and lab/.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace shockgas::app {

// Where the lab's page is: the build tree's (build/share/shockgas/lab) when it
// holds one, else the installed data directory (share/shockgas/lab under the
// install prefix); empty when neither does. The one place the command looks
// for the lab's files.
std::filesystem::path lab_directory();

// Copies the page's files into out_dir (created; the page's files in it
// replaced, any others left) and returns what to tell the user. Throws
// LabMissing when there is no page to copy, RunError when it cannot be written.
std::string write_lab(const std::string& out_dir);

// The lab was not built, or not found: the message says why and what to do.
struct LabMissing : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace shockgas::app

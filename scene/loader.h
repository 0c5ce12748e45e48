// SPDX-License-Identifier: MIT
//
// Reads Radiance scene descriptions (radiance-notes.md §2.3) into a Scene:
// comments, `!command` lines run through /bin/sh (their output parsed as scene
// input), aliases, several files in order. Replaces Radiance's readobj.c and
// the parts of oconv that build the scene.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <memory>
#include <string>
#include <vector>

#include "core/diagnostics.h"
#include "core/function_ref.h"
#include "scene/scene.h"

namespace rt {

struct SceneLoadOptions {
    /// Directory put first on PATH while `!command` lines run, so the bundled
    /// genbox and xform (build/bin/) are found on machines without Radiance.
    /// Empty: PATH unchanged.
    std::string toolDirectory;
    /// False: a `!command` line is an error ("commands disabled") instead of being
    /// run, for untrusted input (the fuzzers in tests/fuzz/).
    bool runCommands = true;
    /// False: `instance` and `mesh` primitives are an error ("files disabled")
    /// instead of reading the files they name, for untrusted input.
    bool readFiles = true;
};

/// Parses one scene stream into raw objects; `name` is used in error locations.
/// Runs `!command` lines (recursively parsing their output) unless
/// options.runCommands is false. Throws rt::Error with "file:line: ..." on
/// malformed input.
std::vector<SceneObject> ReadSceneObjects(std::istream& in, const std::string& name,
                                          const SceneLoadOptions& options,
                                          const WarningSink& warn);

/// The same, each object handed to `onObject` as soon as it is read (it may
/// take the object's strings) instead of being kept. Returns how many.
std::size_t ReadSceneObjects(std::istream& in, const std::string& name,
                             const SceneLoadOptions& options, const WarningSink& warn,
                             FunctionRef<void(SceneObject&)> onObject);

/// Resolves modifiers and aliases and interprets every object. Throws rt::Error
/// naming the object's file:line for undefined modifiers, bad argument counts,
/// unsupported types, degenerate geometry that Radiance treats as fatal.
/// Octrees named by `instance` and mesh files named by `mesh` are found on
/// RAYPATH and read here; `options` applies to the scene files of non-frozen
/// instanced octrees. The objects are taken by value: pass them with
/// std::move and each one's strings become its surface's, with no copy.
Scene BuildScene(std::vector<SceneObject> objects, const WarningSink& warn,
                 const SceneLoadOptions& options = {});

/// BuildScene fed one object at a time, as a reader produces them, so that a
/// large scene's objects are never all held at once: its load time is mostly
/// the first touches of the memory it fills.
class SceneAssembler {
public:
    explicit SceneAssembler(const WarningSink& warn, const SceneLoadOptions& options = {});
    ~SceneAssembler();
    SceneAssembler(const SceneAssembler&) = delete;
    SceneAssembler& operator=(const SceneAssembler&) = delete;

    /// Interprets the next object (BuildScene's errors); a surface takes its strings.
    void Add(SceneObject& object);
    /// Room for `n` more surfaces (and, for a large scene, heap in huge pages).
    void ReserveSurfaces(std::size_t n);
    /// For scene text of `bytes` whose object count is unknown: heap in huge
    /// pages, as ReserveSurfaces reserves it for a counted scene.
    void ReserveForText(std::uintmax_t bytes);
    /// The scene; the assembler is spent.
    Scene Finish();

private:
    class Impl;
    std::unique_ptr<Impl> impl_;
};

struct OctreeFile;
/// The objects an octree describes: its own if frozen, else its scene files
/// re-read relative to the current directory (with their `!commands`) and
/// checked against it (Radiance's stale-octree test). `name` is the octree's,
/// for messages. A frozen octree's objects are moved out of it, not copied.
std::vector<SceneObject> OctreeSceneObjects(OctreeFile& octree, const std::string& name,
                                            const SceneLoadOptions& options,
                                            const WarningSink& warn);

/// A named octree's scene files, re-read relative to the current directory
/// (with their `!commands`), each object handed to `onObject` as it is read.
void ReadOctreeSceneFiles(const OctreeFile& octree, const std::string& name,
                          const SceneLoadOptions& options, const WarningSink& warn,
                          FunctionRef<void(SceneObject&)> onObject);

/// Reads the files in order ("-" is standard input) and builds the scene.
Scene LoadScene(const std::vector<std::string>& files, const SceneLoadOptions& options,
                const WarningSink& warn);

}  // namespace rt

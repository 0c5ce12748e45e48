// SPDX-License-Identifier: MIT
#include "scene/loader.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "scene/octree.h"
#include "scene/radiance_binary.h"
#include "scene/reader.h"

namespace rt {
namespace {

struct ReadContext {
    const SceneLoadOptions& options;
    const WarningSink& warn;
    FunctionRef<void(SceneObject&)> onObject;
    std::size_t objects = 0;  // handed to onObject so far
};

/// Where objects from a command's output say they come from: the command line
/// prefixed by the place it was written, e.g. "room.rad:82: !genbox ...".
std::string CommandSourceName(const FileLoc& loc, const std::string& command) {
    std::string oneLine;
    for (const char c : command) oneLine.push_back(c == '\n' || c == '\r' ? ' ' : c);
    return loc.ToString() + ": !" + oneLine;
}

// `origin` is the outermost `!command` line (in a real file) that led here;
// empty at the top level.
void ReadItems(CharSource& source, const std::string& name, int depth, const FileLoc& origin,
               ReadContext& context);

void RunCommand(const SceneItem& item, int depth, const FileLoc& origin, ReadContext& context) {
    const FileLoc& root = origin.file.empty() ? item.loc : origin;
    std::string shown = "!";
    shown += PrintableWord(item.text);
    if (!context.options.runCommands) ThrowUserError(item.loc, "commands disabled: " + shown);
    if (depth + 1 > kMaxCommandDepth) {
        // Reported at the outermost command: the nested location chain would be 32 deep.
        ThrowUserError(root, "commands nested more than " + std::to_string(kMaxCommandDepth) +
                                     " deep (does a command read its own file?): " + shown);
    }
    CommandPipe pipe(item.text, context.options.toolDirectory, depth + 1);
    if (pipe.source() == nullptr) {
        throw Error(Error::Kind::System, item.loc, "cannot execute " + shown);
    }
    const std::size_t before = context.objects;
    const std::string name = CommandSourceName(item.loc, item.text);
    try {
        ReadItems(*pipe.source(), name, depth + 1, root, context);
    } catch (const Error&) {
        // A command that failed explains its garbage output better than the parser can.
        const std::string failure = pipe.Finish();
        if (!failure.empty()) ThrowUserError(item.loc, "command failed (" + failure + "): " + shown);
        throw;
    }
    const std::string failure = pipe.Finish();
    if (!failure.empty()) ThrowUserError(item.loc, "command failed (" + failure + "): " + shown);
    if (context.objects == before && context.warn) context.warn("(" + name + "): empty file");
}

void ReadItems(CharSource& source, const std::string& name, int depth, const FileLoc& origin,
               ReadContext& context) {
    SceneTextReader reader(source, name);
    for (SceneItem item = reader.Next(); item.kind != SceneItemKind::End; item = reader.Next()) {
        if (item.kind == SceneItemKind::Object) {
            ++context.objects;
            context.onObject(item.object);
        } else if (item.kind == SceneItemKind::Command) {
            RunCommand(item, depth, origin, context);
        }
    }
}

}  // namespace

std::size_t ReadSceneObjects(std::istream& in, const std::string& name,
                             const SceneLoadOptions& options, const WarningSink& warn,
                             FunctionRef<void(SceneObject&)> onObject) {
    ReadContext context{options, warn, onObject};
    IstreamCharSource source(in);
    ReadItems(source, name, InheritedCommandDepth(), FileLoc{}, context);
    if (context.objects == 0 && warn) warn("(" + name + "): empty file");
    return context.objects;
}

std::vector<SceneObject> ReadSceneObjects(std::istream& in, const std::string& name,
                                          const SceneLoadOptions& options,
                                          const WarningSink& warn) {
    std::vector<SceneObject> objects;
    ReadSceneObjects(in, name, options, warn,
                     [&objects](SceneObject& o) { objects.push_back(std::move(o)); });
    return objects;
}

namespace {

/// The whole output of an octree `!command` (rtrace's "!oconv ..." argument).
std::string CommandOutput(const std::string& command, const SceneLoadOptions& options) {
    std::string shown = "!";
    shown.append(PrintableWord(command));  // not "!" + ...: GCC 12 warns falsely (bug 105329)
    if (!options.runCommands) ThrowUserError("commands disabled: " + shown);
    CommandPipe pipe(command, options.toolDirectory, InheritedCommandDepth() + 1);
    if (pipe.source() == nullptr) ThrowSystemError("cannot execute " + shown);
    std::string out;
    for (int c = pipe.source()->Get(); c != std::char_traits<char>::eof(); c = pipe.source()->Get()) {
        out.push_back(static_cast<char>(c));
    }
    const std::string failure = pipe.Finish();
    if (!failure.empty()) ThrowUserError("command failed (" + failure + "): " + shown);
    return out;
}

/// Builds the scene an octree describes, with the octree's cube and header.
Scene LoadOctree(std::istream& in, const std::string& name, const SceneLoadOptions& options,
                 const WarningSink& warn, bool firstLineRead = false) {
    // Either way each object goes into the scene as it is read: a frozen
    // octree's own, or a named one's scene files' (then checked against the
    // octree, as Radiance's readoct does after readobj).
    SceneAssembler assembler(warn, options);
    OctreeFile octree = ReadOctree(
        in, name, firstLineRead, [&assembler](SceneObject& o) { assembler.Add(o); },
        [&assembler](long long count) {
            assembler.ReserveSurfaces(
                static_cast<std::size_t>(std::min(count, detail::kMaxReservedObjects)));
        });
    if (!octree.frozen()) {
        OctreeObjectTally tally;
        ReadOctreeSceneFiles(octree, name, options, warn, [&](SceneObject& o) {
            tally.Add(o);
            assembler.Add(o);
        });
        CheckOctreeObjects(octree, tally, name);
    }
    Scene scene = assembler.Finish();
    // The octree's cube is the scene's: -ar means what it means to Radiance
    // on the same file.
    scene.cubeOrigin = octree.cubeOrigin;
    scene.cubeSize = octree.cubeSize;
    scene.headerLines = octree.headerLines;
    return scene;
}

}  // namespace

void ReadOctreeSceneFiles(const OctreeFile& octree, const std::string& name,
                          const SceneLoadOptions& options, const WarningSink& warn,
                          FunctionRef<void(SceneObject&)> onObject) {
    for (const std::string& file : octree.sceneFiles) {
        std::ifstream f(file, std::ios::binary);
        if (!f) ThrowSystemError(name + ": cannot open its scene file \"" + file + "\"");
        ReadSceneObjects(f, file, options, warn, onObject);
    }
}

std::vector<SceneObject> OctreeSceneObjects(OctreeFile& octree, const std::string& name,
                                            const SceneLoadOptions& options,
                                            const WarningSink& warn) {
    std::vector<SceneObject> objects;
    if (octree.frozen()) {
        objects = std::move(octree.objects);
    } else {
        ReadOctreeSceneFiles(octree, name, options, warn,
                             [&objects](SceneObject& o) { objects.push_back(std::move(o)); });
    }
    CheckOctreeObjects(octree, objects, name);
    return objects;
}

Scene LoadScene(const std::vector<std::string>& files, const SceneLoadOptions& options,
                const WarningSink& warn) {
    // An octree (a file, or the output of a `!command`) is the whole scene,
    // as it is for Radiance's rtrace.
    if (files.size() == 1 && files[0] == "-" && std::cin.peek() == '#') {
        // Standard input cannot be rewound: read its first line, and if it
        // opens an octree, read the rest of it, leaving the rays that follow.
        // Otherwise the scene text goes on after that comment line.
        std::string first;
        std::getline(std::cin, first);
        if (first == "#?RADIANCE") return LoadOctree(std::cin, "<stdin>", options, warn, true);
        SceneAssembler assembler(warn, options);
        ReadSceneObjects(std::cin, "<stdin>", options, warn,
                         [&assembler](SceneObject& o) { assembler.Add(o); });
        return assembler.Finish();
    }
    for (const std::string& file : files) {
        const bool command = file.starts_with("!");
        if (!command && file == "-") continue;
        std::ifstream f;
        std::istringstream commandOut;
        std::istream* in = nullptr;
        if (command) {
            commandOut.str(CommandOutput(file.substr(1), options));
            in = &commandOut;
        } else {
            f.open(file, std::ios::binary);
            if (!f) continue;  // reported below, with the other open errors
            in = &f;
            // An empty file as the only scene is what a failed `oconv > x.oct`
            // leaves: Radiance's rtrace stops on it, where lazyrad would read an
            // empty scene and answer every ray with black.
            std::error_code ec;
            if (files.size() == 1 && std::filesystem::is_regular_file(file, ec) &&
                std::filesystem::file_size(file, ec) == 0 && !ec) {
                const std::string shown = PrintableWord(file);
                ThrowUserError("(" + shown + "): not an octree");
            }
        }
        if (!LooksLikeOctree(*in)) {
            if (command) {
                ThrowUserError("the output of \"" + PrintableWord(file) + "\" is not an octree");
            }
            continue;
        }
        if (files.size() != 1) {
            // Radiance takes one octree and calls any other argument after
            // the options a command line error, named after the first.
            ThrowUserError("command line error at '" + PrintableWord(files.front()) + "'");
        }
        return LoadOctree(*in, file, options, warn);
    }
    // Each object is interpreted as it is read (Radiance's readobj() also
    // resolves modifiers as it goes).
    SceneAssembler assembler(warn, options);
    std::uintmax_t textBytes = 0;  // files only: a pipe's size is unknown
    for (const std::string& file : files) {
        std::error_code ec;
        const std::uintmax_t size = file == "-" ? 0 : std::filesystem::file_size(file, ec);
        if (!ec) textBytes += size;
    }
    assembler.ReserveForText(textBytes);
    const auto add = [&assembler](SceneObject& o) { assembler.Add(o); };
    for (const std::string& file : files) {
        if (file == "-") {
            ReadSceneObjects(std::cin, "<stdin>", options, warn, add);
        } else {
            std::error_code ec;
            if (std::filesystem::is_directory(file, ec)) {
                ThrowSystemError("cannot open scene file \"" + file + "\": is a directory");
            }
            errno = 0;
            std::ifstream in(file, std::ios::binary);
            if (!in) {
                // Radiance's words for its one scene argument, the octree; its
                // system errors end with the C library's reason.
                const int reason = errno;
                ThrowSystemError(std::string(files.size() == 1 ? "cannot open octree file \""
                                                               : "cannot open scene file \"") +
                                 file + "\"" +
                                 (reason != 0 ? std::string(": ") + std::strerror(reason) : ""));
            }
            ReadSceneObjects(in, file, options, warn, add);
            if (in.bad()) ThrowSystemError("error reading scene file \"" + file + "\"");
        }
    }
    return assembler.Finish();
}

}  // namespace rt

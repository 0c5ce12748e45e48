// SPDX-License-Identifier: MIT
#include "scene/loader.h"

#include <filesystem>
#include <fstream>
#include <iostream>

#include "scene/reader.h"

namespace rt {
namespace {

struct ReadContext {
    const SceneLoadOptions& options;
    const WarningSink& warn;
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
               const ReadContext& context, std::vector<SceneObject>& objects);

void RunCommand(const SceneItem& item, int depth, const FileLoc& origin,
                const ReadContext& context, std::vector<SceneObject>& objects) {
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
    const std::size_t before = objects.size();
    const std::string name = CommandSourceName(item.loc, item.text);
    try {
        ReadItems(*pipe.source(), name, depth + 1, root, context, objects);
    } catch (const Error&) {
        // A command that failed explains its garbage output better than the parser can.
        const std::string failure = pipe.Finish();
        if (!failure.empty()) ThrowUserError(item.loc, "command failed (" + failure + "): " + shown);
        throw;
    }
    const std::string failure = pipe.Finish();
    if (!failure.empty()) ThrowUserError(item.loc, "command failed (" + failure + "): " + shown);
    if (objects.size() == before && context.warn) context.warn("(" + name + "): empty file");
}

void ReadItems(CharSource& source, const std::string& name, int depth, const FileLoc& origin,
               const ReadContext& context, std::vector<SceneObject>& objects) {
    SceneTextReader reader(source, name);
    for (SceneItem item = reader.Next(); item.kind != SceneItemKind::End; item = reader.Next()) {
        if (item.kind == SceneItemKind::Object) {
            objects.push_back(std::move(item.object));
        } else if (item.kind == SceneItemKind::Command) {
            RunCommand(item, depth, origin, context, objects);
        }
    }
}

}  // namespace

std::vector<SceneObject> ReadSceneObjects(std::istream& in, const std::string& name,
                                          const SceneLoadOptions& options,
                                          const WarningSink& warn) {
    const ReadContext context{options, warn};
    std::vector<SceneObject> objects;
    IstreamCharSource source(in);
    ReadItems(source, name, InheritedCommandDepth(), FileLoc{}, context, objects);
    if (objects.empty() && warn) warn("(" + name + "): empty file");
    return objects;
}

Scene LoadScene(const std::vector<std::string>& files, const SceneLoadOptions& options,
                const WarningSink& warn) {
    std::vector<SceneObject> objects;
    for (const std::string& file : files) {
        std::vector<SceneObject> more;
        if (file == "-") {
            more = ReadSceneObjects(std::cin, "<stdin>", options, warn);
        } else {
            std::error_code ec;
            if (std::filesystem::is_directory(file, ec)) {
                ThrowSystemError("cannot open scene file \"" + file + "\": is a directory");
            }
            std::ifstream in(file, std::ios::binary);
            if (!in) ThrowSystemError("cannot open scene file \"" + file + "\"");
            more = ReadSceneObjects(in, file, options, warn);
            if (in.bad()) ThrowSystemError("error reading scene file \"" + file + "\"");
        }
        objects.insert(objects.end(), std::make_move_iterator(more.begin()),
                       std::make_move_iterator(more.end()));
    }
    return BuildScene(objects, warn);
}

}  // namespace rt

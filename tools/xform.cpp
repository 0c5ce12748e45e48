// SPDX-License-Identifier: MIT
//
// xform: transforms Radiance scene files (Radiance's xform.c). Options, then
// transforms applied in the order given, then files (standard input if none):
//
//   xform [-c|-e] [-I] [-n prefix] [-m mod] [-t x y z] [-rx|-ry|-rz deg] [-s f]
//         [-mx|-my|-mz] [-i n] [-a n] [file ...]
//
// Comments are copied, `!commands` are run and their output transformed (left
// as commands piped through xform with -c), materials pass through except where
// a length is in their arguments (glow, spotlight, dielectric, interface, mist).
// Errors print one line "xform: ..." and exit with status 1.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "scene/reader.h"
#include "scene/transform.h"

namespace {

using rt::CharSource;
using rt::SceneItem;
using rt::SceneItemKind;

/// Standard input, read once: with -a every run transforms the same input.
struct StdinCache {
    bool read = false;
    std::string text;
};

/// Thrown for command-line and input problems; main prints it and exits 1.
struct XformError {
    std::string message;
};

class Xformer {
public:
    Xformer(std::vector<std::string> args, StdinCache* stdinCopy)
        : args_(std::move(args)), stdinCopy_(stdinCopy) {}

    void Run() {
        ParseOptions();
        std::printf("#");
        for (std::size_t i = 0; i < filesStart_; ++i) std::printf(" %s", args_[i].c_str());
        std::printf("\n");
        if (filesStart_ == args_.size()) {
            if (!stdinCopy_->read) {
                std::ostringstream all;
                all << std::cin.rdbuf();
                stdinCopy_->text = all.str();
                stdinCopy_->read = true;
            }
            std::istringstream in(stdinCopy_->text);
            rt::IstreamCharSource source(in);
            TransformInput(source, "standard input", "");
            return;
        }
        for (std::size_t i = filesStart_; i < args_.size(); ++i) {
            const std::string& file = args_[i];
            std::ifstream in(file, std::ios::binary);
            if (!in) throw XformError{"cannot open file \"" + file + "\""};
            // Like Radiance's xform, commands in a file run in the file's directory.
            const std::size_t slash = file.find_last_of('/');
            const std::string dir =
                slash == std::string::npos ? "" : (slash == 0 ? "/" : file.substr(0, slash));
            rt::IstreamCharSource source(in);
            TransformInput(source, file, dir);
        }
    }

private:
    void ParseOptions() {
        std::size_t a = 1;
        for (; a < args_.size(); ++a) {
            const std::string& option = args_[a];
            if ((option == "-m" || option == "-n") && a + 1 < args_.size()) {
                const std::string& value = args_[++a];
                if (option == "-m") {
                    if (settings_.newModifier.empty()) settings_.newModifier = value;
                } else {
                    settings_.idPrefix =
                        settings_.idPrefix.empty() ? value : settings_.idPrefix + "." + value;
                }
            } else if (option == "-c") {
                expand_ = false;
            } else if (option == "-e") {
                expand_ = true;
            } else if (option == "-I") {
                settings_.invert = !settings_.invert;
            } else {
                break;
            }
        }
        transformStart_ = a;
        const rt::ParsedTransform parsed = rt::ParseTransformArgs(args_, a);
        settings_.transform = parsed.transform;
        filesStart_ = parsed.next;
        if (filesStart_ < args_.size() && !args_[filesStart_].empty() &&
            args_[filesStart_][0] == '-') {
            throw XformError{"command line error at '" + args_[filesStart_] + "'"};
        }
        settings_.transformArgs.assign(args_.begin() + static_cast<std::ptrdiff_t>(transformStart_),
                                       args_.begin() + static_cast<std::ptrdiff_t>(filesStart_));
        depth_ = rt::InheritedCommandDepth();
    }

    /// Transforms one input; warns if it held nothing.
    void TransformInput(CharSource& source, const std::string& name, const std::string& dir) {
        if (TransformStream(source, name, dir) == 0) WarnEmpty(name);
    }

    static void WarnEmpty(const std::string& name) {
        std::fprintf(stderr, "xform: (%s): warning - empty file\n", name.c_str());
    }

    int TransformStream(CharSource& source, const std::string& name, const std::string& dir) {
        rt::SceneTextReader reader(source, name);
        int items = 0;
        for (SceneItem item = reader.Next(); item.kind != SceneItemKind::End; item = reader.Next()) {
            switch (item.kind) {
                case SceneItemKind::Comment:
                    std::printf("%s\n", item.text.c_str());
                    break;
                case SceneItemKind::Command:
                    ++items;
                    Command(item, dir);
                    break;
                case SceneItemKind::Object:
                    ++items;
                    std::fputs(
                        rt::FormatSceneObject(rt::TransformSceneObject(item.object, settings_)).c_str(),
                        stdout);
                    break;
                case SceneItemKind::End:
                    break;
            }
        }
        return items;
    }

    void Command(const SceneItem& item, const std::string& dir) {
        if (!expand_) {
            // Leave the command in place, piped through an xform that will expand it.
            std::string line = "\n!" + item.text;
            if (filesStart_ > 1) {
                line += " | " + args_[0] + " -e";
                for (std::size_t i = 1; i < filesStart_; ++i) {
                    if (i >= transformStart_ || args_[i] != "-c") line += " " + args_[i];
                }
            }
            std::printf("%s\n", line.c_str());
            return;
        }
        std::string shown = "!";  // appended: GCC 12 false -Wrestrict on "!" + temporary
        shown += rt::PrintableWord(item.text);
        if (depth_ + 1 > rt::kMaxCommandDepth) {
            throw XformError{item.loc.ToString() + ": commands nested more than " +
                             std::to_string(rt::kMaxCommandDepth) +
                             " deep (does a command read its own file?): " + shown};
        }
        const std::string command =
            dir.empty() ? item.text : std::string("cd ") + rt::ShellQuote(dir) + " || exit 1\n" + item.text;
        rt::CommandPipe pipe(command, "", depth_ + 1);
        if (pipe.source() == nullptr) {
            throw XformError{item.loc.ToString() + ": cannot execute " + shown};
        }
        const int items = TransformStream(*pipe.source(), "!" + item.text, "");
        const std::string failure = pipe.Finish();
        if (!failure.empty()) {
            throw XformError{item.loc.ToString() + ": command failed (" + failure + "): " + shown};
        }
        if (items == 0) WarnEmpty("!" + item.text);
    }

    std::vector<std::string> args_;
    StdinCache* stdinCopy_;
    rt::XformSettings settings_;
    bool expand_ = true;
    std::size_t transformStart_ = 1;
    std::size_t filesStart_ = 1;
    int depth_ = 0;
};

/// xform -a n: n runs with "-a n" replaced by "-i k" (k = 0 … n−1) and the
/// identifiers prefixed by "a<k>" (or "<prefix>.<k>" when -n is given).
void RunArray(const std::vector<std::string>& args, std::size_t at, StdinCache* stdinCopy) {
    const int count = at + 1 < args.size() && rt::IsIntegerWord(args[at + 1])
                          ? std::atoi(args[at + 1].c_str())
                          : 0;
    if (count <= 0) throw XformError{"missing count for -a option"};
    std::string oldId;
    std::size_t idAt = 0;
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (args[i - 1] == "-n") {
            oldId = args[i];
            idAt = i;
            break;
        }
    }
    for (int k = 0; k < count; ++k) {
        std::vector<std::string> run = args;
        run[at] = "-i";
        run[at + 1] = std::to_string(k);
        if (idAt != 0) {
            run[idAt] = oldId + "." + std::to_string(k);
        } else {
            std::string id = "a";
            id += std::to_string(k);
            run.insert(run.begin() + 1, {"-n", id});
        }
        Xformer(run, stdinCopy).Run();
    }
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv, argv + argc);
    StdinCache stdinCopy;
    try {
        for (const std::string& arg : args) {
            if (arg == "-f") throw XformError{"-f argument files are not supported"};
        }
        std::size_t arrayAt = 0;
        for (std::size_t i = 1; i < args.size(); ++i) {
            if (args[i] == "-a") {
                arrayAt = i;
                break;
            }
        }
        if (arrayAt != 0) {
            RunArray(args, arrayAt, &stdinCopy);
        } else {
            Xformer(args, &stdinCopy).Run();
        }
    } catch (const XformError& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "xform: %s\n", e.message.c_str());
        return 1;
    } catch (const rt::Error& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "xform: %s\n", e.what());
        return 1;
    }
    return std::fflush(stdout) == 0 ? 0 : 1;
}

// SPDX-License-Identifier: MIT
//
// The low-level half of Radiance's readobj.c / fgetword.c / readfargs.c: a
// tokenizer that turns scene text into items (objects, `!command` lines and
// comments) with file:line locations, and a pipe that runs a `!command`.
// ReadSceneObjects() (loader.h) and the xform tool are built on it; xform needs
// the comments and the unexpanded commands, the loader does not.
//
//   FileCharSource source(file);
//   SceneTextReader reader(source, "scene.rad");
//   for (auto item = reader.Next(); item.kind != SceneItemKind::End; item = reader.Next()) ...
#pragma once

#include <cstdio>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace rt {

/// A byte stream read one character at a time (getc semantics: EOF at the end).
class CharSource {
public:
    virtual ~CharSource() = default;
    virtual int Get() = 0;
};

class IstreamCharSource final : public CharSource {
public:
    explicit IstreamCharSource(std::istream& in) : buf_(in.rdbuf()) {}
    int Get() override;

private:
    std::streambuf* buf_;
};

/// Does not own the FILE.
class FileCharSource final : public CharSource {
public:
    explicit FileCharSource(std::FILE* file) : file_(file) {}
    int Get() override { return std::getc(file_); }

private:
    std::FILE* file_;
};

enum class SceneItemKind { Object, Command, Comment, End };

struct SceneItem {
    SceneItemKind kind = SceneItemKind::End;
    SceneObject object;     // Object
    std::string text;       // Command: the line after '!' (backslash-newlines kept);
                            // Comment: the line from '#' on, without the newline
    FileLoc loc;            // where the item starts
};

/// Splits scene text into items. Objects are checked as Radiance's reader checks
/// them (known type, integer counts, integer-argument count 0, numeric reals,
/// `inherit` only on aliases) but modifiers are not resolved. Throws rt::Error
/// (User) with "name:line: ..." on malformed input; never reads past an error.
class SceneTextReader {
public:
    SceneTextReader(CharSource& source, std::string name);

    SceneItem Next();
    const std::string& name() const { return name_; }

private:
    int Peek();
    int Get();
    /// Next whitespace-separated (optionally quoted) word; nullopt at end of input.
    std::optional<std::string> Word();
    std::string RequireWord(const char* what, const SceneObject& object);
    long long Count(const char* what, const SceneObject& object);
    std::string RestOfLine(bool continuation);
    FileLoc Here() const { return FileLoc{name_, line_}; }

    CharSource& source_;
    std::string name_;
    int line_ = 1;
    int peeked_ = -2;  // -2: nothing peeked
};

/// Radiance's isint(): optional sign and digits only.
bool IsIntegerWord(std::string_view word);
/// Radiance's isflt() grammar ([+-] digits [. digits] [e [+-] digits], at least one
/// digit before the exponent) parsed to a finite double; nullopt otherwise.
std::optional<double> ParseRealWord(std::string_view word);
/// A word safe to quote in a message: control and non-ASCII bytes as \xNN, long
/// words cut to 60 characters with "...".
std::string PrintableWord(std::string_view word);
/// 'text' for /bin/sh, with embedded single quotes escaped.
std::string ShellQuote(std::string_view text);

/// Maximum nesting of `!command` lines (and of xform processes expanding them),
/// a guard against a command that reads the file it is in.
inline constexpr int kMaxCommandDepth = 32;
/// Environment variable carrying the nesting depth into child processes.
inline constexpr const char* kCommandDepthVariable = "RT_SCENE_DEPTH";
/// Depth of this process as set by a parent (0 when unset or malformed).
int InheritedCommandDepth();

/// A `!command` running under /bin/sh with its standard output readable through
/// source(). Its standard input is /dev/null (so a command can never swallow
/// rtrace's ray input), `pathPrefix` (if any) is put first on PATH, and
/// RT_SCENE_DEPTH is set to `depth` in the child only.
class CommandPipe {
public:
    CommandPipe(const std::string& command, const std::string& pathPrefix, int depth);
    ~CommandPipe();
    CommandPipe(const CommandPipe&) = delete;
    CommandPipe& operator=(const CommandPipe&) = delete;

    /// nullptr if the shell could not be started.
    CharSource* source() { return source_ ? source_.get() : nullptr; }
    /// Closes the pipe and waits; returns "" on success or a description such as
    /// "exit status 1" / "killed by signal 9".
    std::string Finish();

private:
    std::FILE* pipe_ = nullptr;
    std::unique_ptr<FileCharSource> source_;
};

}  // namespace rt

// SPDX-License-Identifier: MIT
//
// lookamb: print the records of an ambient file as text, or turn that text back
// into a binary ambient file. Same options and output as Radiance's lookamb
// (src/rt/lookamb.c; radiance-notes.md §5.9):
//   lookamb [-d] [-h] [-r|-u|-s] [file]   (standard input if no file)
//   -d  one TAB-separated line per record instead of the labelled form
//   -h  no header: on output omit it; with -r, write a new one instead of copying
//   -r  reverse: read text (labelled, or -d form with -d), write binary to stdout
//   -u  the same as -r (lazyrad's synonym; Radiance has only -r)
//   -s  salvage (lazyrad's): write a binary file of every valid record of a
//       damaged one, re-synchronising after misaligned bytes (ambfiles/salvage.h),
//       with one line on stderr saying what was dropped; the input is only read
// Reading stops silently at the first invalid or truncated record, as Radiance's.
#include <cstdio>
#include <cstring>
#include <iostream>
#include <iterator>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ambfiles/ascii.h"
#include "ambfiles/header.h"
#include "core/portable.h"
#include "ambfiles/record_codec.h"
#include "ambfiles/salvage.h"

namespace {

struct Options {
    bool dataOnly = false;
    bool header = true;
    bool reverse = false;
    bool salvage = false;
};

bool ReadAll(std::FILE* fp, std::string& out) {
    char buf[65536];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, fp)) > 0) out.append(buf, n);
    return !std::ferror(fp);
}

// printargs()/fputword(): words separated by spaces, quoted when they contain blanks.
std::string CommandLine(int argc, char** argv) {
    std::string s;
    for (int i = 0; i < argc; ++i) {
        std::string_view w = argv[i];
        const bool quote = w.empty() || w.find_first_of(" \t\n\"'") != std::string_view::npos;
        if (quote) {
            const char q = w.find('"') != std::string_view::npos ? '\'' : '"';
            s += q;
            s += w;
            s += q;
        } else {
            s += w;
        }
        s += i + 1 < argc ? ' ' : '\n';
    }
    return s;
}

int FormatError(const char* prog) {
    std::fprintf(stderr, "%s: format error on input\n", prog);
    return 1;
}

// Binary -> text.
int Look(const Options& opt, const std::string& input, const char* prog) {
    const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(input.data()),
                                              input.size());
    const rt::HeaderParse parse = rt::ParseAmbientHeader(bytes);
    if (!parse.header) return FormatError(prog);
    std::string out;
    if (opt.header) {
        for (const std::string& line : parse.header->lines) {
            if (!rt::HeaderFormatValue(line)) out += line + "\n";
        }
        out += "FORMAT=ascii\n\n";
    }
    const auto layout = opt.dataOnly ? rt::AmbientTextLayout::DataOnly
                                     : rt::AmbientTextLayout::Labelled;
    for (std::size_t pos = parse.header->recordsOffset; bytes.size() - pos >= rt::kRecordBytes;
         pos += rt::kRecordBytes) {
        auto record = rt::DecodeRecord(
            std::span<const std::uint8_t, rt::kRecordBytes>(bytes.data() + pos, rt::kRecordBytes));
        if (!record) break;
        out += rt::FormatAmbientText(*record, layout);
    }
    if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size()) return 1;
    return 0;
}

// Text -> binary.
int Reverse(const Options& opt, const std::string& input, int argc, char** argv) {
    std::string out;
    std::size_t bodyStart = 0;
    if (opt.header) {
        // checkheader(fp, "ascii", stdout): copy the header minus FORMAT lines; a
        // FORMAT other than ascii is an error.
        std::size_t pos = 0;
        for (;;) {
            const std::size_t end = input.find('\n', pos);
            if (end == std::string::npos) return FormatError(argv[0]);
            const std::string_view line(input.data() + pos, end - pos);
            pos = end + 1;
            if (line.empty() || line == "\r") break;
            if (auto fmt = rt::HeaderFormatValue(line)) {
                if (*fmt != "ascii") return FormatError(argv[0]);
                continue;
            }
            out += line;
            out += '\n';
        }
        bodyStart = pos;
    } else {
        out += "#?RADIANCE\n" + CommandLine(argc, argv);
    }
    out += "FORMAT=" + std::string(rt::kAmbientFormat) + "\n\n";
    std::uint8_t magic[rt::kAmbientMagicBytes];
    rt::PutPortableInt(rt::kAmbientMagic, rt::kAmbientMagicBytes, magic);
    out.append(reinterpret_cast<const char*>(magic), rt::kAmbientMagicBytes);
    const auto layout = opt.dataOnly ? rt::AmbientTextLayout::DataOnly
                                     : rt::AmbientTextLayout::Labelled;
    for (const rt::AmbientRecord& r :
         rt::ParseAmbientText(std::string_view(input).substr(bodyStart), layout)) {
        const rt::RecordBytes b = rt::EncodeRecord(r);
        out.append(reinterpret_cast<const char*>(b.data()), b.size());
    }
    if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size()) return 1;
    return 0;
}

// Damaged binary -> binary of its valid records.
int Salvage(const std::string& input, const char* prog, const char* name) {
    const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(input.data()),
                                              input.size());
    std::string problem;
    const std::optional<rt::SalvageResult> result = rt::SalvageAmbientFile(bytes, &problem);
    if (!result) {
        std::fprintf(stderr, "%s: %s: not an ambient file (%s)\n", prog, name, problem.c_str());
        return 1;
    }
    if (std::fwrite(result->file.data(), 1, result->file.size(), stdout) != result->file.size()) {
        return 1;
    }
    if (result->damagedStretches == 0) {
        std::fprintf(stderr, "%s: %s: %zu records, no damage\n", prog, name, result->records);
    } else {
        std::fprintf(stderr,
                     "%s: %s: %zu records recovered; %zu bytes dropped in %zu damaged stretches, "
                     "the first at byte %lld\n",
                     prog, name, result->records, result->droppedBytes, result->damagedStretches,
                     static_cast<long long>(result->firstDamage));
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    int i = 1;
    for (; i < argc && argv[i][0] == '-'; ++i) {
        switch (argv[i][1]) {
            case 'd': opt.dataOnly = true; break;
            case 'r':
            case 'u':  // -u: lazyrad's synonym ("unparse" back to binary)
                opt.reverse = true;
                break;
            case 'h': opt.header = false; break;
            case 's': opt.salvage = true; break;
            default:
                std::fprintf(stderr, "%s: unknown option '%s'\n", argv[0], argv[i]);
                return 1;
        }
    }
    std::FILE* fp = stdin;
    if (i < argc) {
        fp = std::fopen(argv[i], "rb");
        if (fp == nullptr) {
            std::fprintf(stderr, "%s: file not found\n", argv[i]);
            return 1;
        }
    }
    std::string input;
    const bool ok = ReadAll(fp, input);
    if (fp != stdin) std::fclose(fp);
    if (!ok) {
        std::fprintf(stderr, "%s: read error\n", argv[0]);
        return 1;
    }
    const int rc = opt.salvage   ? Salvage(input, argv[0], i < argc ? argv[i] : "<stdin>")
                   : opt.reverse ? Reverse(opt, input, argc, argv)
                                 : Look(opt, input, argv[0]);
    if (std::fflush(stdout) != 0) return 1;
    return rc;
}

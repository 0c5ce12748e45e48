// SPDX-License-Identifier: MIT
#include "image/hdr.h"

#include <cmath>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>

#include "core/error.h"

namespace rt {
namespace {

constexpr const char* kMagicLine = "#?RADIANCE";
constexpr const char* kFormatRgbe = "32-bit_rle_rgbe";
// Radiance color.c: scanlines outside [kMinEncodedLength, kMaxEncodedLength]
// are always flat; runs shorter than kMinRun are not worth a run code.
constexpr int kMinEncodedLength = 8;
constexpr int kMaxEncodedLength = 0x7fff;
constexpr int kMinRun = 4;
constexpr int kMaxRun = 127;
constexpr int kMaxLiteral = 128;

[[noreturn]] void Corrupt(const std::string& name, std::istream& in, const std::string& what) {
    in.clear();
    const long long offset = static_cast<long long>(in.tellg());
    FileLoc loc{name};
    loc.byteOffset = offset >= 0 ? offset : -1;
    ThrowUserError(loc, "bad Radiance picture: " + what);
}

int GetByte(std::istream& in, const std::string& name) {
    const int c = in.get();
    if (c == std::char_traits<char>::eof())
        Corrupt(name, in, "unexpected end of file");
    return c;
}

void PutByte(std::ostream& out, int b) {
    out.put(static_cast<char>(static_cast<unsigned char>(b)));
}

void WriteScanlineRle(std::ostream& out, const std::vector<Rgbe>& scan) {
    const int len = static_cast<int>(scan.size());
    PutByte(out, 2);
    PutByte(out, 2);
    PutByte(out, len >> 8);
    PutByte(out, len & 255);
    // Components are encoded one after the other, as Radiance's fwritecolrs.
    for (int comp = 0; comp < 4; ++comp) {
        auto at = [&](int i) {
            return scan[static_cast<std::size_t>(i)][static_cast<std::size_t>(comp)];
        };
        int j = 0;
        while (j < len) {
            // Find the next run of at least kMinRun equal bytes, starting at `beg`.
            int beg = j;
            int cnt = 0;
            while (beg < len) {
                cnt = 1;
                while (cnt < kMaxRun && beg + cnt < len && at(beg + cnt) == at(beg))
                    ++cnt;
                if (cnt >= kMinRun)
                    break;
                beg += cnt;
            }
            const bool haveRun = beg < len;
            // A short stretch of 2-3 equal bytes before the run still codes cheaper as a run.
            if (beg - j > 1 && beg - j < kMinRun) {
                bool allSame = true;
                for (int k = j + 1; k < beg; ++k)
                    allSame = allSame && at(k) == at(j);
                if (allSame) {
                    PutByte(out, 128 + beg - j);
                    PutByte(out, at(j));
                    j = beg;
                }
            }
            while (j < beg) {
                const int n = std::min(beg - j, kMaxLiteral);
                PutByte(out, n);
                for (int k = 0; k < n; ++k)
                    PutByte(out, at(j++));
            }
            if (haveRun) {
                PutByte(out, 128 + cnt);
                PutByte(out, at(beg));
                j = beg + cnt;
            }
        }
    }
}

// Radiance's oldreadcolrs(): flat pixels, where (1,1,1,n) repeats the previous
// pixel n·256^k times for the k-th consecutive repeat code.
void ReadScanlineFlat(std::istream& in, const std::string& name, Rgbe* scan, int len) {
    int shift = 0;
    int i = 0;
    while (i < len) {
        Rgbe p;
        for (auto& b : p)
            b = static_cast<std::uint8_t>(GetByte(in, name));
        if (p[0] == 1 && p[1] == 1 && p[2] == 1) {
            if (i == 0)
                Corrupt(name, in, "repeat code at the start of a scanline");
            const long long count = static_cast<long long>(p[3]) << shift;
            if (count > len - i)
                Corrupt(name, in, "scanline overrun in repeat code");
            for (long long k = 0; k < count; ++k, ++i)
                scan[i] = scan[i - 1];
            shift += 8;
        } else {
            scan[i++] = p;
            shift = 0;
        }
    }
}

// Radiance's freadcolrs(): new-style RLE when the scanline starts with 2,2 and
// the length, otherwise flat/old-style.
void ReadScanline(std::istream& in, const std::string& name, std::vector<Rgbe>& scan) {
    const int len = static_cast<int>(scan.size());
    if (len < kMinEncodedLength || len > kMaxEncodedLength) {
        ReadScanlineFlat(in, name, scan.data(), len);
        return;
    }
    const int c0 = GetByte(in, name);
    const int c1 = GetByte(in, name);
    const int c2 = GetByte(in, name);
    const int c3 = GetByte(in, name);
    if (c0 != 2 || c1 != 2 || (c2 & 128)) {
        scan[0] = {static_cast<std::uint8_t>(c0), static_cast<std::uint8_t>(c1),
                   static_cast<std::uint8_t>(c2), static_cast<std::uint8_t>(c3)};
        ReadScanlineFlat(in, name, scan.data() + 1, len - 1);
        return;
    }
    if (((c2 << 8) | c3) != len)
        Corrupt(name, in, "scanline length mismatch");
    for (std::size_t comp = 0; comp < 4; ++comp) {
        int j = 0;
        while (j < len) {
            int code = GetByte(in, name);
            if (code > 128) {
                code &= 127;
                if (code > len - j)
                    Corrupt(name, in, "run overruns scanline");
                const auto value = static_cast<std::uint8_t>(GetByte(in, name));
                while (code--)
                    scan[static_cast<std::size_t>(j++)][comp] = value;
            } else {
                if (code == 0 || code > len - j)
                    Corrupt(name, in, "literal overruns scanline");
                while (code--) {
                    scan[static_cast<std::size_t>(j++)][comp] =
                        static_cast<std::uint8_t>(GetByte(in, name));
                }
            }
        }
    }
}

struct Orientation {
    bool yMajor = true;  // scanlines are rows (else columns)
    bool xDecreasing = false;
    bool yDecreasing = true;  // Radiance's y points up: "-Y" means top row first
    int xRes = 0, yRes = 0;
};

Orientation ParseResolution(const std::string& line, const std::string& name, std::istream& in) {
    std::istringstream ss(line);
    std::string a1, a2;
    long long n1 = 0, n2 = 0;
    std::string rest;
    if (!(ss >> a1 >> n1 >> a2 >> n2) || (ss >> rest) || a1.size() != 2 || a2.size() != 2 ||
        (a1[0] != '-' && a1[0] != '+') || (a2[0] != '-' && a2[0] != '+') ||
        !((a1[1] == 'Y' && a2[1] == 'X') || (a1[1] == 'X' && a2[1] == 'Y')) || n1 <= 0 || n2 <= 0 ||
        n1 > (1 << 20) || n2 > (1 << 20)) {
        Corrupt(name, in, "bad resolution string '" + line + "'");
    }
    Orientation o;
    o.yMajor = a1[1] == 'Y';
    const std::string& ys = o.yMajor ? a1 : a2;
    const std::string& xs = o.yMajor ? a2 : a1;
    o.yDecreasing = ys[0] == '-';
    o.xDecreasing = xs[0] == '-';
    o.yRes = static_cast<int>(o.yMajor ? n1 : n2);
    o.xRes = static_cast<int>(o.yMajor ? n2 : n1);
    return o;
}

}  // namespace

void WriteHdr(std::ostream& out, const Image& image, const std::vector<std::string>& headerLines,
              HdrEncoding encoding) {
    out << kMagicLine << '\n';
    for (const std::string& line : headerLines) {
        if (line.rfind("FORMAT=", 0) == 0 || line.rfind("#?", 0) == 0)
            continue;
        if (line.empty() || line.find('\n') != std::string::npos) {
            ThrowUserError("Radiance header line '" + line + "' is empty or holds a newline");
        }
        out << line << '\n';
    }
    out << "FORMAT=" << kFormatRgbe << "\n\n";
    out << "-Y " << image.height << " +X " << image.width << '\n';
    const bool rle = encoding == HdrEncoding::RunLength && image.width >= kMinEncodedLength &&
                     image.width <= kMaxEncodedLength;
    std::vector<Rgbe> scan(static_cast<std::size_t>(image.width));
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x)
            scan[static_cast<std::size_t>(x)] = EncodeRgbe(image.Get(x, y));
        if (rle) {
            WriteScanlineRle(out, scan);
        } else {
            out.write(reinterpret_cast<const char*>(scan.data()),
                      static_cast<std::streamsize>(4 * scan.size()));
        }
    }
}

void WriteHdr(const std::string& path, const Image& image,
              const std::vector<std::string>& headerLines, HdrEncoding encoding) {
    std::ofstream out(path, std::ios::binary);
    if (!out)
        throw Error(Error::Kind::System, FileLoc{path}, "cannot open for writing");
    WriteHdr(out, image, headerLines, encoding);
    out.flush();
    if (!out)
        throw Error(Error::Kind::System, FileLoc{path}, "write error");
}

Image ReadHdr(std::istream& in, const std::string& name, std::vector<std::string>* headerLines,
              long long maxPixels) {
    std::string line;
    if (!std::getline(in, line) || line.rfind("#?", 0) != 0) {
        ThrowUserError(FileLoc{name, 1}, "not a Radiance picture (no '#?RADIANCE' line)");
    }
    if (headerLines)
        headerLines->clear();
    int lineNo = 1;
    while (true) {
        if (!std::getline(in, line)) {
            ThrowUserError(FileLoc{name, lineNo}, "Radiance picture header does not end");
        }
        ++lineNo;
        if (line.empty())
            break;
        if (line.rfind("FORMAT=", 0) == 0) {
            std::string fmt = line.substr(7);
            while (!fmt.empty() && (fmt.back() == ' ' || fmt.back() == '\t' || fmt.back() == '\r'))
                fmt.pop_back();
            if (fmt != kFormatRgbe) {
                ThrowUserError(FileLoc{name, lineNo}, "unsupported picture format '" + fmt +
                                                          "' (need " + kFormatRgbe + ")");
            }
            continue;
        }
        if (headerLines)
            headerLines->push_back(line);
    }
    if (!std::getline(in, line))
        Corrupt(name, in, "missing resolution string");
    const Orientation o = ParseResolution(line, name, in);
    const long long pixels = static_cast<long long>(o.xRes) * o.yRes;
    if (pixels > maxPixels) {
        Corrupt(name, in, std::to_string(o.xRes) + " x " + std::to_string(o.yRes) +
                              " pixels, more than the " + std::to_string(maxPixels) +
                              " lazyrad reads");
    }
    const int scans = o.yMajor ? o.yRes : o.xRes;
    const int scanLength = o.yMajor ? o.xRes : o.yRes;
    // The scanlines are kept as read, and the picture made only once all are
    // there: memory grows with the data actually decoded, so a short file that
    // declares a huge size stops at its end instead of first filling gigabytes.
    std::vector<Rgbe> stored;
    std::vector<Rgbe> scan(static_cast<std::size_t>(scanLength));
    for (int s = 0; s < scans; ++s) {
        ReadScanline(in, name, scan);
        stored.insert(stored.end(), scan.begin(), scan.end());
    }
    Image image(o.xRes, o.yRes);
    for (int s = 0; s < scans; ++s) {
        const Rgbe* read = stored.data() + static_cast<std::size_t>(s) * scanLength;
        for (int i = 0; i < scanLength; ++i) {
            // (s, i) → Radiance (x, y-up) → our top-down row.
            int x = o.yMajor ? i : s;
            int yUp = o.yMajor ? s : i;
            if (o.xDecreasing)
                x = o.xRes - 1 - x;
            if (o.yDecreasing)
                yUp = o.yRes - 1 - yUp;
            image.Set(x, o.yRes - 1 - yUp, DecodeRgbe(read[i]));
        }
    }
    return image;
}

Image ReadHdr(const std::string& path, std::vector<std::string>* headerLines,
              long long maxPixels) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error(Error::Kind::System, FileLoc{path}, "cannot open");
    return ReadHdr(in, path, headerLines, maxPixels);
}

}  // namespace rt

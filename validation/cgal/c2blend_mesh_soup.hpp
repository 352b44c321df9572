// c2blend_mesh_soup.hpp: the OFF, PLY and OBJ readers of c2blend-cgal-curvature and the
// combinatorial checks of the polygon soup they produce, with messages naming the file,
// the line or element. Shared by the tool and its fuzz target (tests/fuzz/fuzz_mesh.cpp).
// Everything lives in an unnamed namespace: include this header in one translation unit
// per program.
#ifndef C2BLEND_MESH_SOUP_HPP
#define C2BLEND_MESH_SOUP_HPP

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <istream>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace c2blend_mesh {
typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3                Point_3;
typedef Kernel::Vector_3               Vector_3;
}  // namespace c2blend_mesh

namespace {

using c2blend_mesh::Point_3;
using c2blend_mesh::Vector_3;

// One error type for everything the user can get wrong (arguments or input).
struct Input_error : std::runtime_error {
  explicit Input_error(const std::string &what) : std::runtime_error(what) {}
};

template <class... Args> std::string format(const char *fmt, Args... args)
{
  int n = std::snprintf(nullptr, 0, fmt, args...);
  std::string s(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  std::snprintf(&s[0], s.size() + 1, fmt, args...);
  return s;
}

// ---------------------------------------------------------------------------------------
// Input: a polygon soup with optional per-vertex normals and analytic curvature.
// ---------------------------------------------------------------------------------------

struct Soup {
  std::string path;
  std::vector<Point_3> points;
  std::vector<long> point_line;                    // source line of each vertex, 0 if binary
  std::vector<std::vector<std::size_t>> faces;
  std::vector<long> face_line;                     // source line of each face, 0 if binary
  std::vector<Vector_3> normals;                   // empty when the file has none
  bool analytic = false;                           // PLY k1 k2 present
  std::vector<double> k1, k2;
  std::vector<int> region, valid;

  // "FILE, line L: " or "FILE: " for a binary file.
  std::string where(long line) const
  {
    return line > 0 ? format("%s, line %ld: ", path.c_str(), line) : path + ": ";
  }
  std::string vertex_where(std::size_t v) const
  {
    return where(v < point_line.size() ? point_line[v] : 0) + format("vertex %zu: ", v);
  }
  std::string face_where(std::size_t f) const
  {
    return where(f < face_line.size() ? face_line[f] : 0) + format("face %zu: ", f);
  }
};

// Splits a line into whitespace-separated tokens, dropping a '#' comment when asked.
std::vector<std::string> tokens(const std::string &line, bool hash_comments)
{
  std::vector<std::string> out;
  std::size_t i = 0, n = line.size();
  if (hash_comments) {
    std::size_t h = line.find('#');
    if (h != std::string::npos)
      n = h;
  }
  while (i < n) {
    while (i < n && std::isspace(static_cast<unsigned char>(line[i])))
      i++;
    std::size_t j = i;
    while (j < n && !std::isspace(static_cast<unsigned char>(line[j])))
      j++;
    if (j > i)
      out.emplace_back(line, i, j - i);
    i = j;
  }
  return out;
}

// Parses a whole token as a double. "nan", "inf" and overflow (which gives inf) are
// accepted here and rejected by the finiteness checks, so the message says what is wrong
// with the value; underflow to a subnormal or zero is accepted.
bool parse_double(const std::string &s, double &x)
{
  if (s.empty())
    return false;
  char *end = nullptr;
  x = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// Parses a whole token as a (possibly negative) integer.
bool parse_long(const std::string &s, long long &x)
{
  if (s.empty())
    return false;
  char *end = nullptr;
  errno = 0;
  x = std::strtoll(s.c_str(), &end, 10);
  return end == s.c_str() + s.size() && errno != ERANGE;
}

void check_finite(const Soup &soup, std::size_t v, const double *xyz, const char *what)
{
  for (int c = 0; c < 3; c++)
    if (!std::isfinite(xyz[c]))
      throw Input_error(soup.vertex_where(v) +
                        format("non-finite %s coordinate %c = %g", what, "xyz"[c], xyz[c]));
}

std::size_t face_index(const Soup &soup, std::size_t f, long long idx, long line)
{
  if (idx < 0 || static_cast<unsigned long long>(idx) >= soup.points.size())
    throw Input_error(soup.where(line) +
                      format("face %zu: vertex index %lld out of range (the mesh has %zu vertices)",
                             f, idx, soup.points.size()));
  return static_cast<std::size_t>(idx);
}

// Reads the next line, counting lines; strips a trailing '\r'.
bool next_line(std::istream &in, std::string &line, long &lineno)
{
  if (!std::getline(in, line))
    return false;
  lineno++;
  if (!line.empty() && line.back() == '\r')
    line.pop_back();
  return true;
}

// Reads the next line that has tokens (OFF: '#' comments and blank lines are skipped).
bool next_tokens(std::istream &in, std::vector<std::string> &tok, long &lineno)
{
  std::string line;
  while (next_line(in, line, lineno)) {
    tok = tokens(line, true);
    if (!tok.empty())
      return true;
  }
  return false;
}

// --- OFF: [C][N]OFF header, "nv nf ne", one vertex or face per line ------------------

void read_off(std::istream &in, Soup &soup)
{
  long lineno = 0;
  std::vector<std::string> tok;
  if (!next_tokens(in, tok, lineno))
    throw Input_error(soup.path + ": empty file (expected an OFF header)");
  std::string head = tok[0];
  bool colours = false, normals = false;
  std::size_t p = 0;
  if (head.compare(p, 1, "C") == 0 && head.size() > 3)
    colours = true, p++;
  if (head.compare(p, 1, "N") == 0 && head.size() > p + 3)
    normals = true, p++;
  if (head.substr(p) != "OFF")
    throw Input_error(soup.where(lineno) + "expected the header OFF, COFF, NOFF or CNOFF, found '" +
                      head + "'");
  (void)colours; // colours follow the coordinates; they are ignored
  tok.erase(tok.begin());
  if (tok.empty() && !next_tokens(in, tok, lineno))
    throw Input_error(soup.where(lineno) + "missing the counts line 'vertices faces edges'");
  long long nv = 0, nf = 0;
  if (tok.size() < 2 || !parse_long(tok[0], nv) || !parse_long(tok[1], nf) || nv < 0 || nf < 0)
    throw Input_error(soup.where(lineno) + "expected the counts 'vertices faces edges'");
  if (nv == 0)
    throw Input_error(soup.where(lineno) + "empty mesh: 0 vertices");
  std::size_t nvals = normals ? 6 : 3;
  soup.normals.clear();
  for (long long i = 0; i < nv; i++) {
    std::size_t v = static_cast<std::size_t>(i);
    if (!next_tokens(in, tok, lineno))
      throw Input_error(soup.path + format(": unexpected end of file in vertex %zu of %lld", v, nv));
    soup.point_line.push_back(lineno);
    double x[6];
    if (tok.size() < nvals)
      throw Input_error(soup.vertex_where(v) + format("expected %zu numbers, found %zu", nvals, tok.size()));
    for (std::size_t c = 0; c < nvals; c++)
      if (!parse_double(tok[c], x[c]))
        throw Input_error(soup.vertex_where(v) + "'" + tok[c] + "' is not a number");
    soup.points.emplace_back(x[0], x[1], x[2]);
    check_finite(soup, v, x, "vertex");
    if (normals) {
      check_finite(soup, v, x + 3, "normal");
      soup.normals.emplace_back(x[3], x[4], x[5]);
    }
  }
  for (long long i = 0; i < nf; i++) {
    std::size_t f = static_cast<std::size_t>(i);
    if (!next_tokens(in, tok, lineno))
      throw Input_error(soup.path + format(": unexpected end of file in face %zu of %lld", f, nf));
    long long n = 0;
    if (!parse_long(tok[0], n) || n < 0)
      throw Input_error(soup.where(lineno) + format("face %zu: '%s' is not a vertex count", f, tok[0].c_str()));
    if (static_cast<long long>(tok.size()) < n + 1)
      throw Input_error(soup.where(lineno) +
                        format("face %zu: expected %lld vertex indices, found %zu", f, n, tok.size() - 1));
    std::vector<std::size_t> face;
    for (long long j = 1; j <= n; j++) {
      long long idx = 0;
      if (!parse_long(tok[static_cast<std::size_t>(j)], idx))
        throw Input_error(soup.where(lineno) + format("face %zu: '%s' is not a vertex index", f,
                                                      tok[static_cast<std::size_t>(j)].c_str()));
      face.push_back(face_index(soup, f, idx, lineno));
    }
    soup.faces.push_back(face);
    soup.face_line.push_back(lineno);
  }
}

// --- OBJ: v, vn, f (v, v/vt, v//vn, v/vt/vn; negative indices are relative) -----------

void read_obj(std::istream &in, Soup &soup)
{
  long lineno = 0;
  std::string line;
  std::vector<Vector_3> vn;
  std::vector<Vector_3> normal_sum;
  std::vector<long> vn_line;
  struct Corner_normal { std::size_t vertex; long long normal; long line; };
  std::vector<Corner_normal> corners;
  while (next_line(in, line, lineno)) {
    std::vector<std::string> tok = tokens(line, true);
    if (tok.empty())
      continue;
    if (tok[0] == "v" || tok[0] == "vn") {
      if (tok.size() < 4)
        throw Input_error(soup.where(lineno) + "'" + tok[0] + "' needs 3 numbers");
      double x[3];
      for (int c = 0; c < 3; c++)
        if (!parse_double(tok[static_cast<std::size_t>(c + 1)], x[c]))
          throw Input_error(soup.where(lineno) + "'" + tok[static_cast<std::size_t>(c + 1)] +
                            "' is not a number");
      if (tok[0] == "v") {
        std::size_t v = soup.points.size();
        soup.points.emplace_back(x[0], x[1], x[2]);
        soup.point_line.push_back(lineno);
        check_finite(soup, v, x, "vertex");
      } else {
        for (int c = 0; c < 3; c++)
          if (!std::isfinite(x[c]))
            throw Input_error(soup.where(lineno) + format("non-finite normal coordinate %g", x[c]));
        vn.emplace_back(x[0], x[1], x[2]);
        vn_line.push_back(lineno);
      }
    } else if (tok[0] == "f") {
      std::size_t f = soup.faces.size();
      std::vector<std::size_t> face;
      for (std::size_t j = 1; j < tok.size(); j++) {
        std::string t = tok[j];
        std::size_t s1 = t.find('/');
        long long idx = 0;
        if (!parse_long(t.substr(0, s1), idx) || idx == 0)
          throw Input_error(soup.where(lineno) + format("face %zu: '%s' is not a vertex reference", f, t.c_str()));
        idx = idx > 0 ? idx - 1 : static_cast<long long>(soup.points.size()) + idx;
        std::size_t v = face_index(soup, f, idx, lineno);
        face.push_back(v);
        if (s1 != std::string::npos) {
          std::size_t s2 = t.find('/', s1 + 1);
          if (s2 != std::string::npos && s2 + 1 < t.size()) {
            long long n = 0;
            if (!parse_long(t.substr(s2 + 1), n) || n == 0)
              throw Input_error(soup.where(lineno) + format("face %zu: '%s' has a bad normal index", f, t.c_str()));
            corners.push_back({v, n > 0 ? n - 1 : static_cast<long long>(vn.size()) + n, lineno});
          }
        }
      }
      soup.faces.push_back(face);
      soup.face_line.push_back(lineno);
    }
    // vt, g, o, s, usemtl, mtllib, l, ...: not needed
  }
  if (soup.points.empty())
    throw Input_error(soup.path + ": empty mesh: no 'v' lines");
  if (!corners.empty()) {
    soup.normals.assign(soup.points.size(), Vector_3(0, 0, 0));
    for (const Corner_normal &c : corners) {
      if (c.normal < 0 || static_cast<std::size_t>(c.normal) >= vn.size())
        throw Input_error(soup.where(c.line) + format("normal index %lld out of range (the file has %zu 'vn')",
                                                      c.normal + 1, vn.size()));
      const Vector_3 &n = vn[static_cast<std::size_t>(c.normal)];
      double len = std::sqrt(n.squared_length());
      if (len > 0)
        soup.normals[c.vertex] = soup.normals[c.vertex] + n / len;
    }
  }
}

// --- PLY: ascii 1.0, binary_little_endian 1.0, binary_big_endian 1.0 ------------------

enum class Ply_type { i8, u8, i16, u16, i32, u32, f32, f64 };

struct Ply_property {
  std::string name;
  Ply_type type = Ply_type::f64;
  bool list = false;
  Ply_type count_type = Ply_type::u8;
};

struct Ply_element {
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> props;
};

bool ply_type(const std::string &s, Ply_type &t)
{
  static const std::map<std::string, Ply_type> names = {
      {"char", Ply_type::i8},    {"int8", Ply_type::i8},      {"uchar", Ply_type::u8},
      {"uint8", Ply_type::u8},   {"short", Ply_type::i16},    {"int16", Ply_type::i16},
      {"ushort", Ply_type::u16}, {"uint16", Ply_type::u16},   {"int", Ply_type::i32},
      {"int32", Ply_type::i32},  {"uint", Ply_type::u32},     {"uint32", Ply_type::u32},
      {"float", Ply_type::f32},  {"float32", Ply_type::f32},  {"double", Ply_type::f64},
      {"float64", Ply_type::f64}};
  auto it = names.find(s);
  if (it == names.end())
    return false;
  t = it->second;
  return true;
}

std::size_t ply_size(Ply_type t)
{
  switch (t) {
  case Ply_type::i8: case Ply_type::u8: return 1;
  case Ply_type::i16: case Ply_type::u16: return 2;
  case Ply_type::i32: case Ply_type::u32: case Ply_type::f32: return 4;
  case Ply_type::f64: return 8;
  }
  return 8;
}

bool host_is_little_endian()
{
  const std::uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

// Reads the values of one element instance, as doubles, in declaration order; a list
// contributes its count followed by its items.
class Ply_value_reader {
public:
  Ply_value_reader(std::istream &in, const Soup &soup, bool ascii, bool little)
      : in_(in), soup_(soup), ascii_(ascii), swap_(little != host_is_little_endian()) {}

  long line() const { return ascii_ ? lineno_ : 0; }
  void set_line(long l) { lineno_ = l; }

  // Starts an instance: an ASCII instance is one line.
  void begin(const std::string &what)
  {
    what_ = what;
    if (!ascii_)
      return;
    std::string s;
    do {
      if (!next_line(in_, s, lineno_))
        throw Input_error(soup_.path + ": unexpected end of file in " + what_);
      tok_ = tokens(s, false);
    } while (tok_.empty());
    pos_ = 0;
  }
  void end()
  {
    if (ascii_ && pos_ != tok_.size())
      throw Input_error(soup_.where(lineno_) + what_ + format(": %zu values more than the header declares",
                                                               tok_.size() - pos_));
  }
  double value(Ply_type t)
  {
    if (ascii_) {
      if (pos_ >= tok_.size())
        throw Input_error(soup_.where(lineno_) + what_ + ": fewer values than the header declares");
      double x = 0;
      if (!parse_double(tok_[pos_], x))
        throw Input_error(soup_.where(lineno_) + what_ + ": '" + tok_[pos_] + "' is not a number");
      pos_++;
      return x;
    }
    unsigned char b[8];
    std::size_t n = ply_size(t);
    if (!in_.read(reinterpret_cast<char *>(b), static_cast<std::streamsize>(n)))
      throw Input_error(soup_.path + ": binary data end early in " + what_);
    if (swap_)
      std::reverse(b, b + n);
    switch (t) {
    case Ply_type::i8: { std::int8_t v; std::memcpy(&v, b, 1); return v; }
    case Ply_type::u8: return b[0];
    case Ply_type::i16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
    case Ply_type::u16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
    case Ply_type::i32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
    case Ply_type::u32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
    case Ply_type::f32: { float v; std::memcpy(&v, b, 4); return v; }
    case Ply_type::f64: { double v; std::memcpy(&v, b, 8); return v; }
    }
    return 0;
  }
  // The length of a list property (its count, of type t): an integer in [0, 1e6);
  // throws Input_error naming the instance otherwise.
  std::size_t length(Ply_type t)
  {
    double c = value(t);
    if (!(c >= 0 && c == std::floor(c) && c < 1e6))
      throw Input_error(soup_.where(line()) + what_ + format(": bad list length %g", c));
    return static_cast<std::size_t>(c);
  }

private:
  std::istream &in_;
  const Soup &soup_;
  bool ascii_, swap_;
  long lineno_ = 0;
  std::string what_;
  std::vector<std::string> tok_;
  std::size_t pos_ = 0;
};

void read_ply(std::istream &in, Soup &soup)
{
  long lineno = 0;
  std::string line;
  if (!next_line(in, line, lineno))
    throw Input_error(soup.path + ": empty file (expected a PLY header)");
  if (line != "ply")
    throw Input_error(soup.where(lineno) + "expected 'ply' as the first line");
  bool ascii = true, little = true, have_format = false;
  std::vector<Ply_element> elements;
  for (;;) {
    if (!next_line(in, line, lineno))
      throw Input_error(soup.path + ": the PLY header has no end_header");
    std::vector<std::string> tok = tokens(line, false);
    if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info")
      continue;
    if (tok[0] == "end_header")
      break;
    if (tok[0] == "format") {
      if (tok.size() != 3 || tok[2] != "1.0")
        throw Input_error(soup.where(lineno) + "expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      if (tok[1] == "ascii")
        ascii = true;
      else if (tok[1] == "binary_little_endian")
        ascii = false, little = true;
      else if (tok[1] == "binary_big_endian")
        ascii = false, little = false;
      else
        throw Input_error(soup.where(lineno) + "unknown PLY format '" + tok[1] + "'");
      have_format = true;
    } else if (tok[0] == "element") {
      long long n = 0;
      if (tok.size() != 3 || !parse_long(tok[2], n) || n < 0)
        throw Input_error(soup.where(lineno) + "expected 'element NAME COUNT'");
      Ply_element e;
      e.name = tok[1];
      e.count = static_cast<std::size_t>(n);
      elements.push_back(e);
    } else if (tok[0] == "property") {
      if (elements.empty())
        throw Input_error(soup.where(lineno) + "property before any element");
      Ply_property p;
      bool ok = false;
      if (tok.size() == 5 && tok[1] == "list") {
        ok = ply_type(tok[2], p.count_type) && ply_type(tok[3], p.type);
        p.list = true;
        p.name = tok[4];
      } else if (tok.size() == 3) {
        ok = ply_type(tok[1], p.type);
        p.name = tok[2];
      }
      if (!ok)
        throw Input_error(soup.where(lineno) + "bad property declaration '" + line + "'");
      elements.back().props.push_back(p);
    } else {
      throw Input_error(soup.where(lineno) + "unknown PLY header line '" + line + "'");
    }
  }
  if (!have_format)
    throw Input_error(soup.path + ": the PLY header has no format line");

  Ply_value_reader rd(in, soup, ascii, little);
  rd.set_line(lineno);
  bool seen_vertex = false;
  for (const Ply_element &e : elements) {
    if (e.name == "vertex") {
      seen_vertex = true;
      if (e.count == 0)
        throw Input_error(soup.path + ": empty mesh: 'element vertex 0'");
      // Column of each property we use, -1 when absent.
      auto col = [&](const char *name) {
        for (std::size_t i = 0; i < e.props.size(); i++)
          if (e.props[i].name == name && !e.props[i].list)
            return static_cast<int>(i);
        return -1;
      };
      int cx = col("x"), cy = col("y"), cz = col("z"), cnx = col("nx"), cny = col("ny"), cnz = col("nz");
      int ck1 = col("k1"), ck2 = col("k2"), cregion = col("region"), cvalid = col("valid");
      if (cx < 0 || cy < 0 || cz < 0)
        throw Input_error(soup.path + ": the vertex element has no x, y, z properties");
      bool has_n = cnx >= 0 && cny >= 0 && cnz >= 0;
      soup.analytic = ck1 >= 0 && ck2 >= 0;
      std::vector<double> val(e.props.size());
      for (std::size_t v = 0; v < e.count; v++) {
        rd.begin(format("vertex %zu", v));
        for (std::size_t i = 0; i < e.props.size(); i++) {
          const Ply_property &p = e.props[i];
          if (p.list) {
            for (std::size_t j = rd.length(p.count_type); j > 0; j--)
              rd.value(p.type);
          } else {
            val[i] = rd.value(p.type);
          }
        }
        rd.end();
        soup.point_line.push_back(rd.line());
        double xyz[3] = {val[static_cast<std::size_t>(cx)], val[static_cast<std::size_t>(cy)],
                         val[static_cast<std::size_t>(cz)]};
        soup.points.emplace_back(xyz[0], xyz[1], xyz[2]);
        check_finite(soup, v, xyz, "vertex");
        if (has_n) {
          double n[3] = {val[static_cast<std::size_t>(cnx)], val[static_cast<std::size_t>(cny)],
                         val[static_cast<std::size_t>(cnz)]};
          check_finite(soup, v, n, "normal");
          soup.normals.emplace_back(n[0], n[1], n[2]);
        }
        if (soup.analytic) {
          double k[3] = {val[static_cast<std::size_t>(ck1)], val[static_cast<std::size_t>(ck2)], 0.0};
          if (!std::isfinite(k[0]) || !std::isfinite(k[1]))
            throw Input_error(soup.vertex_where(v) +
                              format("non-finite analytic curvature k1 = %g, k2 = %g", k[0], k[1]));
          soup.k1.push_back(val[static_cast<std::size_t>(ck1)]);
          soup.k2.push_back(val[static_cast<std::size_t>(ck2)]);
          double region = cregion >= 0 ? val[static_cast<std::size_t>(cregion)] : 0.0;
          if (!(region >= -2147483648.0 && region <= 2147483647.0))  // NaN too; the cast is UB
            throw Input_error(soup.vertex_where(v) + format("region %g is not an int", region));
          soup.region.push_back(static_cast<int>(region));
          soup.valid.push_back(cvalid >= 0 ? val[static_cast<std::size_t>(cvalid)] != 0 : 1);
        }
      }
    } else if (e.name == "face") {
      if (!seen_vertex)
        throw Input_error(soup.path + ": the face element comes before the vertex element");
      int cidx = -1;
      for (std::size_t i = 0; i < e.props.size(); i++)
        if (e.props[i].list && (e.props[i].name == "vertex_indices" || e.props[i].name == "vertex_index"))
          cidx = static_cast<int>(i);
      if (cidx < 0)
        throw Input_error(soup.path + ": the face element has no list property vertex_indices");
      for (std::size_t f = 0; f < e.count; f++) {
        rd.begin(format("face %zu", f));
        std::vector<std::size_t> face;
        for (std::size_t i = 0; i < e.props.size(); i++) {
          const Ply_property &p = e.props[i];
          std::size_t n = p.list ? rd.length(p.count_type) : 1;
          for (std::size_t j = 0; j < n; j++) {
            double x = rd.value(p.type);
            if (static_cast<int>(i) != cidx)
              continue;
            if (!(x == std::floor(x)))
              throw Input_error(soup.where(rd.line()) + format("face %zu: vertex index %g is not an integer", f, x));
            face.push_back(face_index(soup, f, x < -1e18 || x > 1e18 ? -1 : static_cast<long long>(x), rd.line()));
          }
        }
        rd.end();
        soup.faces.push_back(face);
        soup.face_line.push_back(rd.line());
      }
    } else {
      // Skip elements we do not use (edges, materials, ...), value by value.
      for (std::size_t i = 0; i < e.count; i++) {
        rd.begin(e.name + format(" %zu", i));
        for (const Ply_property &p : e.props) {
          for (std::size_t j = p.list ? rd.length(p.count_type) : 1; j > 0; j--)
            rd.value(p.type);
        }
        rd.end();
      }
    }
  }
  if (!seen_vertex)
    throw Input_error(soup.path + ": empty mesh: no vertex element");
}

// Reads a mesh of format ext ("off", "ply" or "obj", lower case) from in into soup
// (soup.path names the source in messages); throws Input_error.
void read_mesh_stream(std::istream &in, const std::string &ext, Soup &soup)
{
  if (ext == "off")
    read_off(in, soup);
  else if (ext == "ply")
    read_ply(in, soup);
  else
    read_obj(in, soup);
  if (soup.faces.empty())
    throw Input_error(soup.path + format(": empty mesh: %zu vertices but no faces", soup.points.size()));
}

[[maybe_unused]] Soup read_mesh(const std::string &path)
{
  Soup soup;
  soup.path = path;
  std::string ext;
  std::size_t dot = path.find_last_of('.');
  if (dot != std::string::npos)
    ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != "off" && ext != "ply" && ext != "obj")
    throw Input_error(path + ": the extension must be .off, .ply or .obj");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Input_error(path + ": cannot open: " + std::strerror(errno));
  read_mesh_stream(in, ext, soup);
  return soup;
}

// ---------------------------------------------------------------------------------------
// Combinatorial checks with messages naming the face and the line: CGAL's
// is_polygon_soup_a_polygon_mesh() only answers yes or no.
// ---------------------------------------------------------------------------------------

void check_soup(const Soup &soup)
{
  typedef std::pair<std::size_t, std::size_t> Edge;
  struct Edge_use { std::vector<std::size_t> faces; std::vector<bool> forward; };
  std::map<Edge, Edge_use> edges;
  for (std::size_t f = 0; f < soup.faces.size(); f++) {
    const std::vector<std::size_t> &face = soup.faces[f];
    if (face.size() < 3)
      throw Input_error(soup.face_where(f) + format("%zu vertices; a face needs at least 3", face.size()));
    for (std::size_t i = 0; i < face.size(); i++)
      for (std::size_t j = i + 1; j < face.size(); j++)
        if (face[i] == face[j])
          throw Input_error(soup.face_where(f) + format("degenerate: vertex %zu appears twice", face[i]));
    for (std::size_t i = 0; i < face.size(); i++) {
      std::size_t a = face[i], b = face[(i + 1) % face.size()];
      Edge_use &u = edges[Edge(std::min(a, b), std::max(a, b))];
      u.faces.push_back(f);
      u.forward.push_back(a < b);
    }
  }
  for (const auto &e : edges) {
    const Edge_use &u = e.second;
    if (u.faces.size() > 2) {
      std::string list;
      for (std::size_t f : u.faces)
        list += (list.empty() ? "" : ", ") + format("%zu", f) +
                (f < soup.face_line.size() && soup.face_line[f] > 0 ? format(" (line %ld)", soup.face_line[f]) : "");
      throw Input_error(soup.path + format(": non-manifold edge (%zu, %zu) shared by %zu faces: ", e.first.first,
                                           e.first.second, u.faces.size()) + list);
    }
    if (u.faces.size() == 2 && u.forward[0] == u.forward[1])
      throw Input_error(soup.face_where(u.faces[1]) +
                        format("inconsistent orientation: faces %zu and %zu traverse edge (%zu, %zu) in the same "
                               "direction",
                               u.faces[0], u.faces[1], e.first.first, e.first.second));
  }
  // Non-manifold (pinched) vertex: the faces around a vertex must form one fan, i.e. the
  // link (one edge per incident face, between the face's neighbours of the vertex) must
  // be connected.
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> link(soup.points.size());
  for (const auto &face : soup.faces)
    for (std::size_t i = 0; i < face.size(); i++)
      link[face[i]].emplace_back(face[(i + face.size() - 1) % face.size()], face[(i + 1) % face.size()]);
  for (std::size_t v = 0; v < link.size(); v++) {
    if (link[v].size() < 2)
      continue;
    std::unordered_map<std::size_t, std::size_t> parent;
    std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
      while (parent[x] != x)
        x = parent[x] = parent[parent[x]];
      return x;
    };
    for (const auto &e : link[v]) {
      parent.emplace(e.first, e.first);
      parent.emplace(e.second, e.second);
    }
    for (const auto &e : link[v])
      parent[find(e.first)] = find(e.second);
    std::size_t roots = 0;
    for (const auto &p : parent)
      roots += p.first == find(p.first);
    if (roots > 1)
      throw Input_error(soup.vertex_where(v) + format("non-manifold vertex: its faces form %zu separate fans", roots));
  }
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.faces))
    throw Input_error(soup.path + ": the faces do not form an oriented manifold polygon mesh");
}

}  // namespace

#endif

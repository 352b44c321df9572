// c2blend-cgal-curvature: an independent check of C2Blend's analytic curvature.
//
// Estimates the principal curvatures k1 >= k2 at every vertex of a triangle (or polygon)
// mesh with CGAL's jet fitting (CGAL::Monge_via_jet_fitting, Cazals and Pouget,
// "Estimating differential quantities using polynomial fitting of osculating jets",
// Computer Aided Geometric Design 22(2), 2005) and, when the mesh carries the analytic
// curvature written by `c2blend mesh` (PLY vertex properties k1 k2 region valid), compares
// the two per vertex and per region. Shares no code with the C2Blend kernel.
//
// Usage:
//   c2blend-cgal-curvature MESH.{off,ply,obj} [--degree D] [--monge D'] [--rings N | --k K]
//                          [--csv OUT.csv] [--summary OUT.json]
// (defaults: --degree 2 --monge 2 --rings 2; see usage()).
//
// Conventions (the same as C2Blend's, MATH.md section 8): a curvature is positive when the
// surface bends towards the vertex normal; k1 >= k2. The fit is oriented with
// Monge_form::comply_wrt_given_normal() and the vertex normal of the file (PLY nx ny nz,
// OBJ vn, NOFF) when it is present and non-zero, else the area-weighted sum of the normals
// of the incident faces (the face orientation of the file).
//
// Neighbourhoods: --rings N (the default, N = 2) takes the vertices at most N edges away on
// the mesh, which is centrally symmetric on a regular grid whatever its aspect ratio; --k K
// takes the query vertex and its K nearest other vertices (a kd-tree,
// CGAL::Orthogonal_k_neighbor_search), which degenerates on strongly anisotropic grids
// (the K points fall on a few grid lines). The query point is always first in the range
// given to the fitter (it is the origin of CGAL's fitting frame).
//
// Statistics: the summary reports, per region (0 blend, 1 primary 1, 2 primary 2), the
// max, mean and rms absolute errors over three vertex classes: all; interior, where no
// neighbourhood point lies on the mesh border (estimators are biased there); smooth,
// interior and the whole neighbourhood in the vertex's own region (a C2 blend is only C2
// across a trimline, which limits a jet fit straddling it to O(h)). Vertices whose PLY
// valid flag is 0 are excluded.
//
// Exit status: 0 on success, EXIT_FAILURE with one message on stderr (naming the file and
// the line or element) on bad arguments or bad input; nothing is written to stdout then.

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/version.h>

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
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

typedef CGAL::Simple_cartesian<double>                                    Kernel;
typedef Kernel::Point_3                                                   Point_3;
typedef Kernel::Vector_3                                                  Vector_3;
typedef CGAL::Surface_mesh<Point_3>                                       Mesh;
typedef Mesh::Vertex_index                                                vertex_descriptor;
typedef Mesh::Face_index                                                  face_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Point_3>                    Vertex_point_map;
typedef CGAL::Monge_via_jet_fitting<Kernel>                               Monge_via_jet_fitting;
typedef Monge_via_jet_fitting::Monge_form                                 Monge_form;
typedef CGAL::Search_traits_3<Kernel>                                     Traits_base;
typedef CGAL::Search_traits_adapter<vertex_descriptor, Vertex_point_map, Traits_base>
                                                                          Search_traits;
typedef CGAL::Orthogonal_k_neighbor_search<Search_traits>                 Neighbor_search;
typedef Neighbor_search::Tree                                             Search_tree;
typedef Neighbor_search::Distance                                         Search_distance;

namespace {

const char *const kProgram = "c2blend-cgal-curvature";

// Limits (no magic numbers buried in the code).
const int kMinDegree = 2;                 // a jet of degree 1 has no curvature
const int kMaxDegree = 6;                 // (d+1)(d+2)/2 = 28 coefficients
const int kMaxMongeDegree = 4;            // CGAL's Monge form stops at order 4
const int kDefaultK = 24;                 // with --k alone: a 5 x 5 block of a regular grid
const int kDefaultRings = 2;              // the default neighbourhood: 19 points on a regular grid
const int kMaxK = 10000;
const int kMaxRings = 64;
const int kMaxExtraRings = 2;             // growth allowed where --rings N has too few points
const double kConditionWarning = 1e12;    // warn when the fit is that ill-conditioned

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

std::size_t jet_coefficients(int degree)
{
  return static_cast<std::size_t>((degree + 1) * (degree + 2) / 2);
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
            double n = rd.value(p.count_type);
            for (long j = 0; j < static_cast<long>(n); j++)
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
          soup.region.push_back(cregion >= 0 ? static_cast<int>(val[static_cast<std::size_t>(cregion)]) : 0);
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
          std::size_t n = 1;
          if (p.list) {
            double c = rd.value(p.count_type);
            if (!(c >= 0 && c == std::floor(c) && c < 1e6))
              throw Input_error(soup.where(rd.line()) + format("face %zu: bad list length %g", f, c));
            n = static_cast<std::size_t>(c);
          }
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
          std::size_t n = 1;
          if (p.list) {
            double c = rd.value(p.count_type);
            n = c >= 0 && c < 1e9 ? static_cast<std::size_t>(c) : 0;
          }
          for (std::size_t j = 0; j < n; j++)
            rd.value(p.type);
        }
        rd.end();
      }
    }
  }
  if (!seen_vertex)
    throw Input_error(soup.path + ": empty mesh: no vertex element");
}

Soup read_mesh(const std::string &path)
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
  if (ext == "off")
    read_off(in, soup);
  else if (ext == "ply")
    read_ply(in, soup);
  else
    read_obj(in, soup);
  if (soup.faces.empty())
    throw Input_error(path + format(": empty mesh: %zu vertices but no faces", soup.points.size()));
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

// ---------------------------------------------------------------------------------------
// Options
// ---------------------------------------------------------------------------------------

struct Options {
  std::string mesh, csv, summary;
  int degree = 2, monge = 2;
  int k = kDefaultK;
  int rings = kDefaultRings; // > 0: use rings instead of the k nearest
};

void usage(FILE *out)
{
  std::fprintf(out,
      "usage: %s MESH.{off,ply,obj} [--degree D] [--monge D'] [--rings N | --k K]\n"
      "                              [--csv OUT.csv] [--summary OUT.json]\n"
      "\n"
      "Principal curvatures k1 >= k2 at every vertex by CGAL %s jet fitting\n"
      "(Monge_via_jet_fitting), compared with the analytic values of a C2Blend PLY.\n"
      "  --degree D   jet degree, %d..%d (default 2); needs (D+1)(D+2)/2 points\n"
      "  --monge D'   Monge form degree, 2..min(D, %d) (default 2); does not change k1, k2\n"
      "  --rings N    neighbourhood: the vertices at most N edges away on the mesh (default\n"
      "               %d); grown by up to %d rings where it has too few points (borders)\n"
      "  --k K        neighbourhood: the vertex and its K nearest vertices (kd-tree; %d if\n"
      "               given alone); needs a roughly isotropic mesh\n"
      "  --csv F      per-vertex table (written atomically)\n"
      "  --summary F  JSON summary (written atomically): per region the max, mean and rms\n"
      "               absolute errors over all, interior and smooth vertices\n"
      "Interior: no neighbourhood point on the mesh border. Smooth: interior and the whole\n"
      "neighbourhood in the vertex's region (the fit does not straddle a trimline).\n"
      "CSV columns with analytic data: vertex,region,x,y,z,k1_est,k2_est,k1_exact,k2_exact,\n"
      "err1,err2,condition,interior,smooth (err = est - exact; nan where the file marks the\n"
      "vertex invalid); without: vertex,x,y,z,k1_est,k2_est,condition,interior.\n"
      "Curvature is positive when the surface bends towards the vertex normal (PLY nx ny nz,\n"
      "OBJ vn, NOFF normals, else the area-weighted normal of the incident faces).\n",
      kProgram, CGAL_VERSION_STR, kMinDegree, kMaxDegree, kMaxMongeDegree, kDefaultRings, kMaxExtraRings,
      kDefaultK);
}

int int_arg(int argc, char **argv, int &i, int lo, int hi)
{
  std::string opt = argv[i];
  long long x = 0;
  if (i + 1 >= argc || !parse_long(argv[i + 1], x) || x < lo || x > hi)
    throw Input_error(opt + format(" needs an integer in [%d, %d]", lo, hi));
  i++;
  return static_cast<int>(x);
}

std::string str_arg(int argc, char **argv, int &i)
{
  if (i + 1 >= argc || argv[i + 1][0] == '\0')
    throw Input_error(std::string(argv[i]) + " needs a file name");
  return argv[++i];
}

Options parse_options(int argc, char **argv)
{
  Options o;
  bool have_k = false, have_rings = false;
  for (int i = 1; i < argc; i++) {
    std::string a = argv[i];
    if (a == "--degree")
      o.degree = int_arg(argc, argv, i, kMinDegree, kMaxDegree);
    else if (a == "--monge")
      o.monge = int_arg(argc, argv, i, 2, kMaxMongeDegree);
    else if (a == "--k")
      o.k = int_arg(argc, argv, i, 1, kMaxK), have_k = true;
    else if (a == "--rings")
      o.rings = int_arg(argc, argv, i, 1, kMaxRings), have_rings = true;
    else if (a == "--csv")
      o.csv = str_arg(argc, argv, i);
    else if (a == "--summary")
      o.summary = str_arg(argc, argv, i);
    else if (a.size() > 1 && a[0] == '-')
      throw Input_error("unknown option " + a);
    else if (o.mesh.empty())
      o.mesh = a;
    else
      throw Input_error("more than one mesh file: '" + o.mesh + "' and '" + a + "'");
  }
  if (o.mesh.empty())
    throw Input_error("missing the mesh file");
  if (have_k && have_rings)
    throw Input_error("--k and --rings exclude each other");
  if (have_k)
    o.rings = 0;
  if (o.monge > o.degree)
    throw Input_error(format("--monge %d exceeds the jet degree %d", o.monge, o.degree));
  if (o.rings == 0 && static_cast<std::size_t>(o.k) + 1 < jet_coefficients(o.degree))
    throw Input_error(format("--k %d gives %d points with the query; a degree-%d jet needs at least %zu (--k %zu)",
                             o.k, o.k + 1, o.degree, jet_coefficients(o.degree), jet_coefficients(o.degree) - 1));
  return o;
}

// ---------------------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------------------

// Writes PATH through a temporary file in the same directory and rename(2), so readers
// never see a partial file.
void write_atomically(const std::string &path, const std::function<void(FILE *)> &body)
{
  std::string tmp = path + ".tmpXXXXXX";
  std::vector<char> name(tmp.begin(), tmp.end());
  name.push_back('\0');
  int fd = mkstemp(name.data());
  if (fd < 0)
    throw Input_error(path + ": cannot create a temporary file: " + std::strerror(errno));
  FILE *fp = fdopen(fd, "w");
  if (!fp) {
    int e = errno;
    close(fd);
    unlink(name.data());
    throw Input_error(path + ": " + std::strerror(e));
  }
  try {
    body(fp);
  } catch (...) {
    std::fclose(fp);
    unlink(name.data());
    throw;
  }
  // mkstemp creates mode 0600; give the usual permissions of a new file.
  mode_t mask = umask(0);
  umask(mask);
  bool ok = !std::ferror(fp) && std::fflush(fp) == 0 && fchmod(fileno(fp), 0666 & ~mask) == 0 &&
            fsync(fileno(fp)) == 0;
  int e = errno;
  ok = std::fclose(fp) == 0 && ok;
  if (!ok || std::rename(name.data(), path.c_str()) != 0) {
    e = ok ? errno : e;
    unlink(name.data());
    throw Input_error(path + ": cannot write: " + std::strerror(e));
  }
}

// A JSON number; NaN and infinities become null.
std::string jnum(double x)
{
  return std::isfinite(x) ? format("%.17g", x) : std::string("null");
}

std::string jstr(const std::string &s)
{
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\')
      out += '\\', out += static_cast<char>(c);
    else if (c < 0x20)
      out += format("\\u%04x", c);
    else
      out += static_cast<char>(c);
  }
  return out + "\"";
}

// Error statistics of one curvature over a set of vertices.
struct Error_stats {
  double max = 0, sum = 0, sum2 = 0;
  long worst = -1;
  void add(double err, std::size_t v)
  {
    double a = std::fabs(err);
    if (a > max || worst < 0)
      max = a, worst = static_cast<long>(v);
    sum += a;
    sum2 += a * a;
  }
  std::string json(std::size_t n) const
  {
    return format("{\"max_abs\": %s, \"mean_abs\": %s, \"rms\": %s, \"worst_vertex\": %ld}",
                  jnum(n ? max : NAN).c_str(), jnum(n ? sum / n : NAN).c_str(),
                  jnum(n ? std::sqrt(sum2 / n) : NAN).c_str(), worst);
  }
};

struct Region_stats {
  std::size_t count = 0;
  Error_stats k1, k2;
  void add(double e1, double e2, std::size_t v)
  {
    count++;
    k1.add(e1, v);
    k2.add(e2, v);
  }
  std::string json() const
  {
    return format("{\"count\": %zu, \"k1\": %s, \"k2\": %s}", count, k1.json(count).c_str(), k2.json(count).c_str());
  }
};

// The three vertex classes of the report: all; interior (no neighbourhood point on the
// mesh border); smooth (interior, and every neighbourhood point in the vertex's own region,
// so the fit does not straddle a trimline, where a C2 blend is only C2).
struct Region_report {
  Region_stats all, interior, smooth;
};

std::string region_name(int r)
{
  switch (r) {
  case 0: return "blend";
  case 1: return "primary1";
  case 2: return "primary2";
  default: return format("region%d", r);
  }
}

// ---------------------------------------------------------------------------------------
// Curvature estimation
// ---------------------------------------------------------------------------------------

struct Estimate {
  double k1 = NAN, k2 = NAN, condition = NAN;
  bool fitted = false, interior = false, smooth = false;
};

int run(const Options &opt)
{
  Soup soup = read_mesh(opt.mesh);
  check_soup(soup);

  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.faces, mesh);
  Vertex_point_map vpm = mesh.points();
  const std::size_t nv = mesh.number_of_vertices();

  // Vertex normals: the file's when present and non-zero, else the area-weighted sum of
  // the incident face normals (each face's vector area, exact for planar polygons).
  std::vector<Vector_3> normal(nv, Vector_3(0, 0, 0));
  for (face_descriptor f : mesh.faces()) {
    Vector_3 area(0, 0, 0);
    Point_3 c = vpm[mesh.target(mesh.halfedge(f))];
    for (auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      area = area + CGAL::cross_product(vpm[mesh.source(h)] - c, vpm[mesh.target(h)] - c);
    for (vertex_descriptor v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      normal[v] = normal[v] + area;
  }
  std::vector<char> normal_from_file(nv, 0);
  if (!soup.normals.empty())
    for (std::size_t i = 0; i < nv; i++)
      if (soup.normals[i].squared_length() > 0) {
        normal[i] = soup.normals[i];
        normal_from_file[i] = 1;
      }

  // Border vertices and isolated vertices (no incident face: skipped, not an error).
  std::vector<char> border(nv, 0), isolated(nv, 0);
  std::size_t n_border = 0, n_isolated = 0;
  for (vertex_descriptor v : mesh.vertices()) {
    isolated[v] = mesh.is_isolated(v);
    border[v] = !isolated[v] && mesh.is_border(v, true);
    n_border += border[v] != 0;
    n_isolated += isolated[v] != 0;
  }

  // Neighbourhood search structures.
  std::vector<vertex_descriptor> used;
  for (vertex_descriptor v : mesh.vertices())
    if (!isolated[v])
      used.push_back(v);
  Search_tree tree(used.begin(), used.end(), Search_tree::Splitter(), Search_traits(vpm));
  Search_distance distance(vpm);
  if (opt.rings == 0)
    tree.build();
  std::vector<int> ring_mark(nv, -1);

  const std::size_t need = jet_coefficients(opt.degree);
  // Gathers the neighbourhood of v, v first. Returns the number of rings used: at least
  // --rings, more when that many rings have fewer than `need` points (at a border or a
  // corner of an open mesh, as CGAL's own mesh example does), at most kMaxExtraRings more.
  auto gather = [&](vertex_descriptor v, std::vector<vertex_descriptor> &nb) {
    nb.clear();
    nb.push_back(v);
    int r = 0;
    if (opt.rings > 0) {
      ring_mark[v] = static_cast<int>(v);
      std::size_t begin = 0;
      for (; r < opt.rings + kMaxExtraRings && (r < opt.rings || nb.size() < need) && begin < nb.size(); r++) {
        std::size_t end = nb.size();
        for (std::size_t i = begin; i < end; i++)
          for (vertex_descriptor w : CGAL::vertices_around_target(mesh.halfedge(nb[i]), mesh))
            if (ring_mark[w] != static_cast<int>(v)) {
              ring_mark[w] = static_cast<int>(v);
              nb.push_back(w);
            }
        begin = end;
      }
    } else {
      Neighbor_search search(tree, vpm[v], static_cast<unsigned int>(opt.k + 1), 0, true, distance);
      for (auto it = search.begin(); it != search.end(); ++it)
        if (it->first != v && nb.size() < static_cast<std::size_t>(opt.k) + 1)
          nb.push_back(it->first);
    }
    return r;
  };

  std::vector<Estimate> est(nv);
  std::vector<vertex_descriptor> nb;
  std::vector<Point_3> pts;
  Monge_via_jet_fitting fitter;
  std::size_t ill_conditioned = 0, grown = 0;
  for (vertex_descriptor v : mesh.vertices()) {
    if (isolated[v])
      continue;
    int rings = gather(v, nb);
    if (opt.rings > 0 && nb.size() < need)
      throw Input_error(soup.vertex_where(v) +
                        format("too few neighbours: %zu points within %d rings (the vertex included; --rings %d "
                               "grown by up to %d); a degree-%d jet needs at least %zu",
                               nb.size(), opt.rings + kMaxExtraRings, opt.rings, kMaxExtraRings, opt.degree, need));
    if (opt.rings == 0 && nb.size() < static_cast<std::size_t>(opt.k) + 1)
      throw Input_error(soup.vertex_where(v) +
                        format("too few neighbours: %zu points (the vertex included; the mesh has %zu vertices in "
                               "faces); --k %d needs %d, a degree-%d jet at least %zu",
                               nb.size(), used.size(), opt.k, opt.k + 1, opt.degree, need));
    grown += rings > opt.rings && opt.rings > 0;
    if (normal[v].squared_length() == 0 || !std::isfinite(normal[v].squared_length()))
      throw Input_error(soup.vertex_where(v) + "no normal to orient the fit (zero normal and zero face area)");
    pts.clear();
    bool interior = true, one_region = true;
    for (vertex_descriptor w : nb) {
      pts.push_back(vpm[w]); // the query point first
      interior = interior && !border[w];
      one_region = one_region && (!soup.analytic || soup.region[w] == soup.region[v]);
    }
    Monge_form monge = fitter(pts.begin(), pts.end(), static_cast<std::size_t>(opt.degree),
                              static_cast<std::size_t>(opt.monge));
    monge.comply_wrt_given_normal(normal[v]);
    Estimate &e = est[v];
    e.k1 = monge.principal_curvatures(0);
    e.k2 = monge.principal_curvatures(1);
    e.condition = fitter.condition_number();
    e.fitted = true;
    e.interior = interior;
    e.smooth = interior && one_region;
    if (!std::isfinite(e.k1) || !std::isfinite(e.k2))
      throw Input_error(soup.vertex_where(v) +
                        format("the jet fit failed (k1 = %g, k2 = %g, condition number %g): the %zu neighbourhood "
                               "points do not determine a degree-%d jet",
                               e.k1, e.k2, e.condition, nb.size(), opt.degree));
    ill_conditioned += !(e.condition < kConditionWarning);
  }

  // Statistics per region over three vertex classes; vertices marked invalid are excluded.
  std::map<int, Region_report> regions;
  std::size_t n_invalid = 0, n_fitted = 0, n_interior = 0, n_smooth = 0, file_normals = 0;
  double cond_max = 0, cond_sum = 0, k1_min = INFINITY, k1_max = -INFINITY, k2_min = INFINITY, k2_max = -INFINITY;
  for (std::size_t i = 0; i < nv; i++) {
    const Estimate &e = est[i];
    if (!e.fitted)
      continue;
    n_fitted++;
    n_interior += e.interior;
    n_smooth += e.smooth;
    file_normals += normal_from_file[i] != 0;
    cond_max = std::max(cond_max, e.condition);
    cond_sum += e.condition;
    k1_min = std::min(k1_min, e.k1), k1_max = std::max(k1_max, e.k1);
    k2_min = std::min(k2_min, e.k2), k2_max = std::max(k2_max, e.k2);
    if (!soup.analytic)
      continue;
    if (!soup.valid[i]) {
      n_invalid++;
      continue;
    }
    double e1 = e.k1 - soup.k1[i], e2 = e.k2 - soup.k2[i];
    Region_report &r = regions[soup.region[i]];
    r.all.add(e1, e2, i);
    if (e.interior)
      r.interior.add(e1, e2, i);
    if (e.smooth)
      r.smooth.add(e1, e2, i);
  }

  const std::string neighbourhood = opt.rings > 0 ? format("%d-ring", opt.rings) : format("%d nearest", opt.k);
  if (!opt.csv.empty())
    write_atomically(opt.csv, [&](FILE *o) {
      if (soup.analytic)
        std::fprintf(o, "vertex,region,x,y,z,k1_est,k2_est,k1_exact,k2_exact,err1,err2,condition,interior,smooth\n");
      else
        std::fprintf(o, "vertex,x,y,z,k1_est,k2_est,condition,interior\n");
      for (std::size_t i = 0; i < nv; i++) {
        const Point_3 &p = soup.points[i];
        const Estimate &e = est[i];
        if (soup.analytic) {
          bool ok = soup.valid[i] && e.fitted;
          std::fprintf(o, "%zu,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d\n", i,
                       soup.region[i], p.x(), p.y(), p.z(), e.k1, e.k2, soup.k1[i], soup.k2[i],
                       ok ? e.k1 - soup.k1[i] : NAN, ok ? e.k2 - soup.k2[i] : NAN, e.condition, e.interior ? 1 : 0,
                       e.smooth ? 1 : 0);
        } else {
          std::fprintf(o, "%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d\n", i, p.x(), p.y(), p.z(), e.k1, e.k2,
                       e.condition, e.interior ? 1 : 0);
        }
      }
    });

  if (!opt.summary.empty())
    write_atomically(opt.summary, [&](FILE *o) {
      std::fprintf(o, "{\n  \"tool\": \"%s\",\n  \"cgal_version\": \"%s\",\n  \"mesh\": %s,\n", kProgram,
                   CGAL_VERSION_STR, jstr(opt.mesh).c_str());
      std::fprintf(o, "  \"vertices\": %zu,\n  \"faces\": %zu,\n  \"border_vertices\": %zu,\n", nv,
                   static_cast<std::size_t>(mesh.number_of_faces()), n_border);
      std::fprintf(o, "  \"isolated_vertices\": %zu,\n  \"fitted_vertices\": %zu,\n", n_isolated, n_fitted);
      std::fprintf(o, "  \"interior_vertices\": %zu,\n  \"smooth_vertices\": %zu,\n", n_interior, n_smooth);
      std::fprintf(o, "  \"jet_degree\": %d,\n  \"monge_degree\": %d,\n", opt.degree, opt.monge);
      if (opt.rings > 0)
        std::fprintf(o, "  \"neighbourhood\": {\"kind\": \"rings\", \"rings\": %d, \"grown\": %zu},\n",
                     opt.rings, grown);
      else
        std::fprintf(o, "  \"neighbourhood\": {\"kind\": \"k_nearest\", \"k\": %d},\n", opt.k);
      std::fprintf(o, "  \"normals\": {\"from_file\": %zu, \"from_faces\": %zu},\n", file_normals,
                   n_fitted - file_normals);
      std::fprintf(o, "  \"condition_number\": {\"max\": %s, \"mean\": %s, \"above_%g\": %zu},\n",
                   jnum(cond_max).c_str(), jnum(n_fitted ? cond_sum / n_fitted : NAN).c_str(), kConditionWarning,
                   ill_conditioned);
      std::fprintf(o, "  \"estimates\": {\"k1_min\": %s, \"k1_max\": %s, \"k2_min\": %s, \"k2_max\": %s},\n",
                   jnum(k1_min).c_str(), jnum(k1_max).c_str(), jnum(k2_min).c_str(), jnum(k2_max).c_str());
      std::fprintf(o, "  \"analytic\": %s", soup.analytic ? "true" : "false");
      if (soup.analytic) {
        std::fprintf(o, ",\n  \"invalid_vertices_excluded\": %zu,\n  \"regions\": {", n_invalid);
        bool first = true;
        for (const auto &r : regions) {
          std::fprintf(o, "%s\n    %s: {\"region\": %d,\n      \"all\": %s,\n      \"interior\": %s,\n"
                          "      \"smooth\": %s}",
                       first ? "" : ",", jstr(region_name(r.first)).c_str(), r.first, r.second.all.json().c_str(),
                       r.second.interior.json().c_str(), r.second.smooth.json().c_str());
          first = false;
        }
        std::fprintf(o, "\n  }");
      }
      std::fprintf(o, "\n}\n");
    });

  // A short report on stdout.
  std::printf("%s: %zu vertices (%zu on the border, %zu interior, %zu smooth), %zu faces; jet degree %d, "
              "Monge degree %d, %s; condition number max %.3g\n",
              opt.mesh.c_str(), nv, n_border, n_interior, n_smooth, static_cast<std::size_t>(mesh.number_of_faces()),
              opt.degree, opt.monge, neighbourhood.c_str(), cond_max);
  if (soup.analytic) {
    for (const auto &r : regions) {
      const Region_stats *cls[] = {&r.second.all, &r.second.interior, &r.second.smooth};
      const char *names[] = {"all", "interior", "smooth"};
      for (int c = 0; c < 3; c++) {
        const Region_stats &a = *cls[c];
        std::printf("  %-9s %-8s %7zu", c == 0 ? region_name(r.first).c_str() : "", names[c], a.count);
        if (a.count)
          std::printf(": |k1 err| max %.3e mean %.3e, |k2 err| max %.3e mean %.3e", a.k1.max, a.k1.sum / a.count,
                      a.k2.max, a.k2.sum / a.count);
        std::printf("\n");
      }
    }
    if (n_invalid)
      std::printf("  %zu vertices marked invalid are excluded\n", n_invalid);
  } else {
    std::printf("  k1 in [%.6g, %.6g], k2 in [%.6g, %.6g]\n", k1_min, k1_max, k2_min, k2_max);
  }
  if (grown)
    std::printf("  %zu neighbourhoods (at borders) were grown beyond %d rings to reach %zu points\n", grown,
                opt.rings, need);
  if (n_isolated)
    std::fprintf(stderr, "%s: warning: %zu vertices belong to no face and were skipped\n", kProgram, n_isolated);
  if (ill_conditioned)
    std::fprintf(stderr, "%s: warning: %zu fits have a condition number above %g\n", kProgram, ill_conditioned,
                 kConditionWarning);
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char **argv)
{
  for (int i = 1; i < argc; i++)
    if (!std::strcmp(argv[i], "-h") || !std::strcmp(argv[i], "--help")) {
      usage(stdout);
      return EXIT_SUCCESS;
    }
  try {
    Options opt = parse_options(argc, argv);
    return run(opt);
  } catch (const Input_error &e) {
    std::fprintf(stderr, "%s: %s\n", kProgram, e.what());
    if (argc < 2)
      usage(stderr);
    return EXIT_FAILURE;
  } catch (const std::bad_alloc &) {
    std::fprintf(stderr, "%s: out of memory\n", kProgram);
    return EXIT_FAILURE;
  } catch (const std::exception &e) {
    std::fprintf(stderr, "%s: %s\n", kProgram, e.what());
    return EXIT_FAILURE;
  }
}

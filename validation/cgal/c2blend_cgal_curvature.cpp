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

#include "c2blend_mesh_soup.hpp"

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

typedef c2blend_mesh::Kernel                                              Kernel;  // Point_3, Vector_3 in the header
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

std::size_t jet_coefficients(int degree)
{
  return static_cast<std::size_t>((degree + 1) * (degree + 2) / 2);
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

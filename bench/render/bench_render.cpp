// bench_render: shadetool's renderer against Mesa's software OpenGL (OSMesa, llvmpipe) rendering the
// same mesh at the same size with the same lights, in one process: Gouraud (ours: bake + raster;
// Mesa: fixed-function per-vertex lighting) and Phong (ours: per-sample equation; Mesa: a GLSL
// per-fragment Blinn-Phong shader). UV spheres of about 10k and 1M triangles at 1920x1080, one
// sample per pixel, filling most of the image. Wall-clock medians, runs interleaved (ours, Mesa,
// ours, Mesa, ...) so that load on the shared machine hits both alike.
//
// Threads: ours in a TBB arena of T slots; llvmpipe with LP_NUM_THREADS (T = 1: 0 rasteriser
// threads, all work on the calling thread; T = 2: 2 rasteriser threads), set before the context
// is created, hence one process per T.
//
// Usage: bench_render THREADS [REPEATS [MESHES [SHADING]]]   (REPEATS default 5; MESHES "all"
// (default) or "10k": the 10k-triangle sphere only; SHADING "all" (default), "gouraud" or "phong")
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include <shadetool/lighting/look_at.h>
#include <shadetool/render/render_mesh.h>
#include "support/analytic_meshes.h"

using namespace shadetool;

namespace {

constexpr int kWidth = 1920, kHeight = 1080;
int g_repeats = 5;

double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU time of the whole process (every thread, llvmpipe's included): other processes on the
// shared machine disturb it much less than wall time.
double cpu_ms() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

// The scene both renderers draw: a directional and a point light, Blinn-Phong, local viewer.
Scene bench_scene() {
  Scene s;
  s.model = ShadingModel::BlinnPhong;
  s.global_ambient = {0.1, 0.1, 0.1};
  s.material.ambient = {1, 1, 1};
  s.material.diffuse = {0.8, 0.5, 0.3};
  s.material.specular = {0.5, 0.5, 0.5};
  s.material.shininess = 32;
  Light d;
  d.type = LightType::Directional;
  d.direction = {-1, -1, -2};
  Light p;
  p.type = LightType::Point;
  p.position = {2, 2, 3};
  s.lights = {d, p};
  look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, s.camera_from_world);
  s.has_camera = true;
  s.lens.fov_y_degrees = 45;
  s.lens.near = 1;
  s.lens.far = 5;
  return s;
}

// ---- Mesa
PFNGLCREATESHADERPROC glCreateShader_;
PFNGLSHADERSOURCEPROC glShaderSource_;
PFNGLCOMPILESHADERPROC glCompileShader_;
PFNGLCREATEPROGRAMPROC glCreateProgram_;
PFNGLATTACHSHADERPROC glAttachShader_;
PFNGLLINKPROGRAMPROC glLinkProgram_;
PFNGLUSEPROGRAMPROC glUseProgram_;
PFNGLGETPROGRAMIVPROC glGetProgramiv_;
PFNGLGETSHADERIVPROC glGetShaderiv_;
PFNGLGETSHADERINFOLOGPROC glGetShaderInfoLog_;

template <class F>
void load(F& f, const char* name) {
  f = reinterpret_cast<F>(OSMesaGetProcAddress(name));
  if (!f) {
    std::fprintf(stderr, "bench_render: OSMesa has no %s\n", name);
    std::exit(1);
  }
}

// Fixed-function lighting uses the same equation (OpenGL 2.1 2.14.1); the shader writes it out per
// fragment for the same two lights (eye space; the modelview is the view, the light positions are
// given in world space and transformed by it when set, as glLightfv does).
const char* kVertexShader = R"(#version 120
varying vec3 p_eye;
varying vec3 n_eye;
void main() {
  p_eye = vec3(gl_ModelViewMatrix * gl_Vertex);
  n_eye = gl_NormalMatrix * gl_Normal;
  gl_Position = ftransform();
})";
const char* kFragmentShader = R"(#version 120
varying vec3 p_eye;
varying vec3 n_eye;
void main() {
  vec3 n = normalize(n_eye);
  vec3 v = normalize(-p_eye);
  vec4 c = gl_FrontLightModelProduct.sceneColor;
  for (int i = 0; i < 2; ++i) {
    vec3 l;
    float att = 1.0;
    if (gl_LightSource[i].position.w == 0.0) {
      l = normalize(gl_LightSource[i].position.xyz);
    } else {
      vec3 d = gl_LightSource[i].position.xyz - p_eye;
      float dist = length(d);
      l = d / dist;
      att = 1.0 / (gl_LightSource[i].constantAttenuation + gl_LightSource[i].linearAttenuation * dist +
                   gl_LightSource[i].quadraticAttenuation * dist * dist);
    }
    float nl = dot(n, l);
    c += att * gl_FrontLightProduct[i].ambient;
    if (nl > 0.0) {
      c += att * nl * gl_FrontLightProduct[i].diffuse;
      float nh = max(dot(n, normalize(l + v)), 0.0);
      c += att * pow(nh, gl_FrontMaterial.shininess) * gl_FrontLightProduct[i].specular;
    }
  }
  gl_FragColor = vec4(c.rgb, 1.0);
})";

struct MesaRenderer {
  OSMesaContext ctx = nullptr;
  std::vector<unsigned char> buffer;
  unsigned phong_program = 0;
  std::vector<float> positions, normals;
  std::vector<unsigned> indices;

  MesaRenderer(const Mesh& mesh, const std::vector<double>& vertex_normals, const Scene& s) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
    ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx) {
      std::fprintf(stderr, "bench_render: OSMesaCreateContextAttribs failed\n");
      std::exit(1);
    }
    buffer.resize(std::size_t(kWidth) * kHeight * 4);
    if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight)) std::exit(1);
    load(glCreateShader_, "glCreateShader");
    load(glShaderSource_, "glShaderSource");
    load(glCompileShader_, "glCompileShader");
    load(glCreateProgram_, "glCreateProgram");
    load(glAttachShader_, "glAttachShader");
    load(glLinkProgram_, "glLinkProgram");
    load(glUseProgram_, "glUseProgram");
    load(glGetProgramiv_, "glGetProgramiv");
    load(glGetShaderiv_, "glGetShaderiv");
    load(glGetShaderInfoLog_, "glGetShaderInfoLog");

    positions.assign(mesh.positions.begin(), mesh.positions.end());
    normals.assign(vertex_normals.begin(), vertex_normals.end());
    indices.assign(mesh.corner_vertex.begin(), mesh.corner_vertex.end());

    glViewport(0, 0, kWidth, kHeight);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    const double top = s.lens.near * std::tan(0.5 * s.lens.fov_y_degrees * 3.14159265358979323846 / 180);
    glFrustum(-top * kWidth / kHeight, top * kWidth / kHeight, -top, top, s.lens.near, s.lens.far);
    glMatrixMode(GL_MODELVIEW);
    double m[16] = {0};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) m[4 * c + r] = s.camera_from_world.A.m[r][c];
      m[12 + r] = s.camera_from_world.t[r];
    }
    m[15] = 1;
    glLoadMatrixd(m);  // lights are given in world space: transformed by the view, as OpenGL does
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const float ambient[4] = {float(s.global_ambient.x), float(s.global_ambient.y), float(s.global_ambient.z), 1};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
      const Light& L = s.lights[i];
      const GLenum id = GLenum(GL_LIGHT0 + i);
      glEnable(id);
      float pos[4];
      if (L.type == LightType::Directional) {
        pos[0] = float(-L.direction.x), pos[1] = float(-L.direction.y), pos[2] = float(-L.direction.z), pos[3] = 0;
      } else {
        pos[0] = float(L.position.x), pos[1] = float(L.position.y), pos[2] = float(L.position.z), pos[3] = 1;
      }
      glLightfv(id, GL_POSITION, pos);
      const float dif[4] = {float(L.diffuse.x), float(L.diffuse.y), float(L.diffuse.z), 1};
      const float spe[4] = {float(L.specular.x), float(L.specular.y), float(L.specular.z), 1};
      glLightfv(id, GL_DIFFUSE, dif);
      glLightfv(id, GL_SPECULAR, spe);
      glLightf(id, GL_CONSTANT_ATTENUATION, float(L.attenuation.x));
      glLightf(id, GL_LINEAR_ATTENUATION, float(L.attenuation.y));
      glLightf(id, GL_QUADRATIC_ATTENUATION, float(L.attenuation.z));
    }
    const Material& mat = s.material;
    const float ka[4] = {float(mat.ambient.x), float(mat.ambient.y), float(mat.ambient.z), 1};
    const float kd[4] = {float(mat.diffuse.x), float(mat.diffuse.y), float(mat.diffuse.z), 1};
    const float ks[4] = {float(mat.specular.x), float(mat.specular.y), float(mat.specular.z), 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ka);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, kd);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, ks);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, float(mat.shininess));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, positions.data());
    glNormalPointer(GL_FLOAT, 0, normals.data());

    auto compile = [](GLenum type, const char* src) {
      const unsigned sh = glCreateShader_(type);
      glShaderSource_(sh, 1, &src, nullptr);
      glCompileShader_(sh);
      int ok = 0;
      glGetShaderiv_(sh, GL_COMPILE_STATUS, &ok);
      if (!ok) {
        char log[2048];
        glGetShaderInfoLog_(sh, sizeof log, nullptr, log);
        std::fprintf(stderr, "bench_render: shader: %s\n", log);
        std::exit(1);
      }
      return sh;
    };
    phong_program = glCreateProgram_();
    glAttachShader_(phong_program, compile(GL_VERTEX_SHADER, kVertexShader));
    glAttachShader_(phong_program, compile(GL_FRAGMENT_SHADER, kFragmentShader));
    glLinkProgram_(phong_program);
    int linked = 0;
    glGetProgramiv_(phong_program, GL_LINK_STATUS, &linked);
    if (!linked) {
      std::fprintf(stderr, "bench_render: shader program did not link\n");
      std::exit(1);
    }
  }
  ~MesaRenderer() { OSMesaDestroyContext(ctx); }

  void draw(bool phong) {
    glUseProgram_(phong ? phong_program : 0);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, GLsizei(indices.size()), GL_UNSIGNED_INT, indices.data());
    glFinish();
  }
  // Mean |ours - Mesa| in 8-bit codes over pixels both cover (ours quantised linearly, as Mesa
  // stores; GL's rows run bottom to top), and how many pixels only one of them covers.
  void compare(const ImageRGB& ours, double& mean_codes, std::size_t& only_one) const {
    double sum = 0;
    std::size_t both = 0;
    only_one = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const unsigned char* m = &buffer[4 * (std::size_t(kHeight - 1 - y) * kWidth + x)];
        const float* o = ours.pixel(x, y);
        const bool mesa_on = (m[0] | m[1] | m[2]) != 0, ours_on = o[0] > 0 || o[1] > 0 || o[2] > 0;
        if (mesa_on != ours_on) ++only_one;
        if (!(mesa_on && ours_on)) continue;
        ++both;
        for (int c = 0; c < 3; ++c) sum += std::fabs(std::lround(255 * std::min(1.0f, std::max(0.0f, o[c]))) - m[c]);
      }
    mean_codes = both ? sum / double(3 * both) : 0;
  }
  double coverage() const {
    std::size_t lit = 0;
    for (std::size_t i = 0; i < buffer.size(); i += 4) lit += (buffer[i] | buffer[i + 1] | buffer[i + 2]) != 0;
    return double(lit) / double(kWidth * kHeight);
  }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int threads = argc > 1 ? std::atoi(argv[1]) : 1;
  if (argc > 2) g_repeats = std::max(1, std::atoi(argv[2]));
  if (threads < 1) return 2;
  setenv("LP_NUM_THREADS", threads == 1 ? "0" : std::to_string(threads).c_str(), 1);
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);  // pin the driver (softpipe differs and is 14x slower)

  std::printf("# bench_render: %dx%d, 1 sample/pixel, %d thread(s), medians of %d wall-clock runs\n", kWidth, kHeight,
              threads, g_repeats);
  std::printf("%-10s %-8s %9s %9s %7s %9s %9s %7s %8s %8s %9s %8s\n", "triangles", "shading", "ours_ms", "mesa_ms",
              "ratio", "ours_cpu", "mesa_cpu", "ratio", "cover_o", "cover_m", "diff_8bit", "only_one");
  const Scene scene = bench_scene();
  std::vector<std::pair<int, int>> spheres{{100, 51}, {1000, 501}};
  if (argc > 3 && std::string(argv[3]) == "10k") spheres.pop_back();
  for (const auto& [nu, nv] : spheres) {
    const Mesh mesh = testing::uv_sphere(nu, nv).mesh;
    const std::vector<double> normals = shading_vertex_normals(mesh);
    MesaRenderer mesa(mesh, normals, scene);
    for (RenderShading shading : {RenderShading::Gouraud, RenderShading::Phong}) {
      if (argc > 4 && std::string(argv[4]) != "all" && std::string(argv[4]) != render_shading_name(shading)) continue;
      RenderOptions o;
      o.shading = shading;
      o.width = kWidth;
      o.height = kHeight;
      o.threads = threads;
      o.check_eye_inside = false;  // not part of drawing (Mesa has nothing like it)
      std::vector<double> ours, theirs, ours_cpu, theirs_cpu;
      double ours_cover = 0;
      ImageRGB last;
      for (int r = 0; r < g_repeats + 1; ++r) {  // run 0 warms up
        double t0 = now_ms(), c0 = cpu_ms();
        const RenderResult res = render_mesh(mesh, scene, o);
        const double t_ours = now_ms() - t0, c_ours = cpu_ms() - c0;
        ours_cover = double(res.stats.samples_covered) / double(kWidth * kHeight);
        if (r == g_repeats) last = res.image;
        t0 = now_ms(), c0 = cpu_ms();
        mesa.draw(shading == RenderShading::Phong);
        const double t_mesa = now_ms() - t0, c_mesa = cpu_ms() - c0;
        if (r > 0) {
          ours.push_back(t_ours);
          theirs.push_back(t_mesa);
          ours_cpu.push_back(c_ours);
          theirs_cpu.push_back(c_mesa);
        }
      }
      const double mo = median(ours), mm = median(theirs), co = median(ours_cpu), cm = median(theirs_cpu);
      double mean_codes = 0;
      std::size_t only_one = 0;
      mesa.compare(last, mean_codes, only_one);
      std::printf("%-10zu %-8s %9.1f %9.1f %7.2f %9.1f %9.1f %7.2f %8.3f %8.3f %9.3f %8zu\n", mesh.num_faces(),
                  render_shading_name(shading), mo, mm, mo / mm, co, cm, co / cm, ours_cover, mesa.coverage(),
                  mean_codes, only_one);
      std::fflush(stdout);
    }
  }
  return 0;
}

#include "cli/plot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "analysis/legs.hpp"
#include "analysis/time_series.hpp"
#include "io/hdf5.hpp"

namespace dem {

namespace {

namespace fs = std::filesystem;

// A string in gnuplot's single quotes (a quote inside doubled).
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

// Runs gnuplot on `script`; its exit status (127 if it could not be started).
int run_gnuplot(const std::string& script) {
  const pid_t pid = fork();
  if (pid == 0) {
    execlp("gnuplot", "gnuplot", script.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  if (pid < 0 || waitpid(pid, &status, 0) < 0) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

// The script and the data of a plot, in a folder of their own in the temporary folder.
void write_plot(const std::string& folder, const std::vector<PlotSeries>& series, const PlotText& text) {
  std::string plots;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const std::string data = folder + "/" + std::to_string(i) + ".dat";
    std::ofstream out(data);
    char line[64];
    for (std::size_t r = 0; r < series[i].x.size() && r < series[i].y.size(); ++r) {
      std::snprintf(line, sizeof line, "%.17g %.17g\n", series[i].x[r], series[i].y[r]);  // every double exactly
      out << line;
    }
    if (!out.flush()) throw std::runtime_error(data + ": cannot write");
    plots += (i ? ", " : "plot ") + quoted(data) + " using 1:2 with lines lw 2 title " + quoted(series[i].key);
  }
  std::ofstream gp(folder + "/plot.gp");
  if (text.term == "png")
    gp << "set terminal pngcairo size 900,600 font ',11' noenhanced\nset output " << quoted(text.out) << "\n";
  else
    gp << "set terminal dumb size 100,30 noenhanced\n" << (text.out.empty() ? "" : "set output " + quoted(text.out) + "\n");
  gp << "set grid lc rgb '#dddddd'\nset key top left box opaque noenhanced\n"
     << "set xlabel " << quoted(text.xlabel) << "\nset ylabel " << quoted(text.ylabel) << "\n"
     << "set title " << quoted(text.title) << "\n"
     << plots << "\n";
  if (!gp.flush()) throw std::runtime_error(folder + "/plot.gp: cannot write");
}

// The key of a result: its file name, and for a partial one its status.
std::string key_of(const std::string& file, hid_t f) {
  std::string key = fs::path(file).filename().string();
  const std::string status = h5::has_attribute(f, "status") ? h5::get_string_attribute(f, "status") : "missing";
  if (status != "complete") key += " (partial: " + status.substr(0, 40) + ")";
  return key;
}

// The x and y columns of a result, keyed by its file name.
PlotSeries read_series(const std::string& file, const PlotArgs& args) {
  h5::Handle f = h5::open_file_read(file);
  const std::string group = args.legs ? "legs" : "timeseries";
  if (!h5::exists(f, group)) throw std::invalid_argument(file + " has no /" + group);
  h5::Handle g = h5::open_group(f, group);
  for (const std::string& n : {args.x, args.y})
    if (!h5::exists(g, n)) throw std::invalid_argument(file + ": /" + group + " has no column '" + n + "'");
  PlotSeries s;
  std::size_t cols = 0;
  s.x = h5::read<double>(g, args.x, cols);
  s.y = h5::read<double>(g, args.y, cols);
  s.key = key_of(file, f);
  return s;
}

}  // namespace

std::string axis_label(const std::string& name, bool legs) {
  for (const auto& c : legs ? leg_columns() : series_columns())
    if (c.name == name) return c.units.empty() || c.units == "1" ? name : name + " [" + c.units + "]";
  throw std::invalid_argument("no column '" + name + "' in " + (legs ? "/legs" : "/timeseries") + " (dem columns" +
                              (legs ? " --legs" : "") + " lists them)");
}

void draw_plot(const std::vector<PlotSeries>& series, const PlotText& text) {
  if (text.term != "png" && text.term != "dumb") throw std::invalid_argument("term must be png or dumb, got '" + text.term + "'");
  if (text.term == "png" && text.out.empty()) throw std::invalid_argument("a png needs a file to go to (--out FILE.png)");
  if (series.empty()) throw std::invalid_argument("nothing to draw");
  std::string folder = (fs::temp_directory_path() / "dem-plot-XXXXXX").string();
  if (!mkdtemp(folder.data()))
    throw std::runtime_error("cannot make a folder in " + fs::temp_directory_path().string() + ": " + std::strerror(errno));
  std::error_code ec;
  try {
    write_plot(folder, series, text);
  } catch (...) {
    fs::remove_all(folder, ec);
    throw;
  }
  const int rc = run_gnuplot(folder + "/plot.gp");
  if (rc == 127) {
    fs::remove_all(folder, ec);
    throw std::runtime_error("cannot run gnuplot (Debian's gnuplot-nox)");
  }
  if (rc != 0) throw std::runtime_error("gnuplot failed (exit " + std::to_string(rc) + "); its script and data are in " + folder);
  fs::remove_all(folder, ec);
}

int plot(const PlotArgs& args) {
  PlotText text;
  text.out = args.out;
  text.term = args.term.empty() ? (args.out.empty() ? "dumb" : "png") : args.term;
  text.title = args.title.empty() ? args.y + " against " + args.x : args.title;
  std::vector<PlotSeries> series;
  try {
    text.xlabel = axis_label(args.x, args.legs), text.ylabel = axis_label(args.y, args.legs);
    for (const std::string& file : args.results) series.push_back(read_series(file, args));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: dem plot: %s\n", e.what());
    return 2;
  }
  try {
    draw_plot(series, text);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: dem plot: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: dem plot: %s\n", e.what());
    return 1;
  }
  if (text.term == "png") std::fprintf(stderr, "%s\n", text.out.c_str());
  return 0;
}

}  // namespace dem

// `socsim batch`: batch generation on a running server (POST /api/v1/batches) for labs — submit
// prompts × seeds or N households, follow the progress, cancel, and download the dataset tar.
// Talks HTTP to --server (default $SOCSIM_SERVER, else http://127.0.0.1:8080) with --key
// (default $SOCSIM_API_KEY) as the Bearer key.
#include <httplib.h>

#include <iostream>
#include <sstream>
#include <thread>

#include "core/common/json_io.hpp"
#include "server/cli/cli.hpp"
#include "server/registry.hpp"

namespace socsim::server {
namespace {

constexpr const char* kBatchUsage =
    "  batch submit (--file REQUEST.json | --prompt TEXT | --prompts-file FILE) --seeds N|A-B [--duration "
    "S]\n"
    "               | --households N [--rooms A-B] [--residents A-B] [--seed S]\n"
    "               [--server URL] [--key KEY] [--wait] [--out DATASET.tar]   queue a batch on a server\n"
    "  batch status ID | batch wait ID [--out DATASET.tar] | batch export ID --out DATASET.tar | batch "
    "cancel ID\n";

struct Remote {
  std::string server;
  std::string key;
};

Remote remote(const CliArgs& a) {
  Remote r;
  const char* s = std::getenv("SOCSIM_SERVER");
  const char* k = std::getenv("SOCSIM_API_KEY");
  r.server = a.opt("--server").value_or(s && *s ? s : "http://127.0.0.1:8080");
  r.key = a.opt("--key").value_or(k ? k : "");
  return r;
}

struct Reply {
  int status = 0;
  std::string body;
};

Result<Reply> call(const Remote& r, const std::string& method, const std::string& path,
                   const std::string& body = {}) {
  httplib::Client c(r.server);
  c.set_connection_timeout(5, 0);
  c.set_read_timeout(120, 0);
  httplib::Headers h;
  if (!r.key.empty()) h.emplace("Authorization", "Bearer " + r.key);
  httplib::Result res = method == "POST"     ? c.Post(path.c_str(), h, body, "application/json")
                        : method == "DELETE" ? c.Delete(path.c_str(), h)
                                             : c.Get(path.c_str(), h);
  if (!res)
    return fail(ErrorCode::kUpstream, "cannot reach " + r.server + " (" + httplib::to_string(res.error()) +
                                          "); is `socsim serve` running?");
  return Reply{res->status, res->body};
}

// The server could not be reached (no problem document to show).
int unreachable(const Error& e) {
  std::cerr << "socsim: " << e.detail << "\n";
  return 1;
}

// A problem document from the server, printed as the CLI prints errors.
int report_reply(const Reply& rep) {
  try {
    const Json p = Json::parse(rep.body);
    std::cerr << "socsim: " << p.value("detail", p.value("title", "request failed")) << "\n";
    for (const auto& e : p.value("errors", Json::array()))
      std::cerr << "  " << e.value("pointer", "") << ": " << e.value("message", "") << "\n";
  } catch (const std::exception&) {
    std::cerr << "socsim: the server answered " << rep.status << "\n";
  }
  return rep.status >= 500 ? 1 : 2;
}

// "N" → [1, N]; "A-B" → [A, B].
std::optional<std::pair<std::int64_t, std::int64_t>> span(const std::string& text) {
  try {
    std::size_t used = 0;
    const auto dash = text.find('-');
    if (dash == std::string::npos) {
      const long long n = std::stoll(text, &used);
      if (used == text.size() && n >= 1) return std::pair<std::int64_t, std::int64_t>(1, n);
      return std::nullopt;
    }
    const long long a = std::stoll(text.substr(0, dash), &used);
    if (used != dash) return std::nullopt;
    const std::string rest = text.substr(dash + 1);
    const long long b = std::stoll(rest, &used);
    if (used == rest.size() && a >= 0 && b >= a) return std::pair<std::int64_t, std::int64_t>(a, b);
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

Result<Json> request_of(const CliArgs& a) {
  if (auto file = a.opt("--file")) {
    auto text = cli_read_file(*file);
    if (!text) return tl::unexpected(text.error());
    try {
      return Json::parse(*text);
    } catch (const std::exception& e) {
      return fail(ErrorCode::kBadRequest, *file + " is not JSON: " + e.what());
    }
  }
  if (auto n = a.opt("--households")) {
    Json r = {{"kind", "households"}};
    try {
      r["count"] = std::stoll(*n);
    } catch (const std::exception&) {
      return fail(ErrorCode::kBadRequest, "--households takes a number of households");
    }
    for (const char* k : {"rooms", "residents"})
      if (auto v = a.opt(std::string("--") + k)) {
        auto s = span(*v);
        if (!s) return fail(ErrorCode::kBadRequest, std::string("--") + k + " takes N or A-B");
        r[k] = {s->first, s->second};
      }
    if (auto s = a.opt("--seed")) r["seed"] = std::stoll(*s);
    return r;
  }
  std::vector<std::string> prompts;
  if (auto p = a.opt("--prompt")) prompts.push_back(*p);
  if (auto f = a.opt("--prompts-file")) {
    auto text = cli_read_file(*f);
    if (!text) return tl::unexpected(text.error());
    std::istringstream in(*text);
    for (std::string line; std::getline(in, line);)
      if (line.find_first_not_of(" \t\r") != std::string::npos) prompts.push_back(line);
  }
  if (prompts.empty())
    return fail(ErrorCode::kBadRequest, "give --file, --prompt, --prompts-file or --households");
  const auto seeds = span(a.opt("--seeds").value_or("1"));
  if (!seeds) return fail(ErrorCode::kBadRequest, "--seeds takes N (1..N) or A-B");
  Json r = {{"kind", "scenarios"},
            {"prompts", prompts},
            {"seeds", {{"first", seeds->first}, {"count", seeds->second - seeds->first + 1}}}};
  if (auto d = a.opt("--duration")) {
    try {
      r["parameters"]["duration_s"] = std::stod(*d);
    } catch (const std::exception&) {
      return fail(ErrorCode::kBadRequest, "--duration takes seconds");
    }
  }
  return r;
}

void print_status(const Json& b) {
  const Json& c = b["counts"];
  std::cerr << "\r" << b.value("id", "") << "  " << b.value("status", "") << "  "
            << static_cast<int>(b.value("progress", 0.0) * 100) << " %  succeeded " << c.value("succeeded", 0)
            << "/" << b.value("total", 0) << ", running " << c.value("running", 0) << ", failed "
            << c.value("failed", 0) << ", cancelled " << c.value("cancelled", 0) << "   " << std::flush;
}

int export_to(const Remote& r, const std::string& id, const std::string& out) {
  auto rep = call(r, "GET", "/api/v1/batches/" + id + "/export");
  if (!rep) return unreachable(rep.error());
  if (rep->status != 200) return report_reply(*rep);
  if (auto s = cli_write_file(out, rep->body); !s) return cli_report(s.error());
  std::cout << out << " (" << rep->body.size() << " bytes)\n";
  return 0;
}

int wait_for(const Remote& r, const std::string& id, const std::optional<std::string>& out) {
  for (;;) {
    auto rep = call(r, "GET", "/api/v1/batches/" + id);
    if (!rep) return unreachable(rep.error());
    if (rep->status != 200) return report_reply(*rep);
    const Json b = Json::parse(rep->body);
    print_status(b);
    if (b["status"] != "running") {
      std::cerr << "\n";
      if (out) return export_to(r, id, *out);
      return b["status"] == "succeeded" ? 0 : 1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
}

int submit(const std::vector<std::string>& args) {
  const CliArgs a = parse_cli(args);
  auto request = request_of(a);
  if (!request) {
    std::cerr << "usage:\n" << kBatchUsage;
    return cli_report(request.error());
  }
  const Remote r = remote(a);
  auto rep = call(r, "POST", "/api/v1/batches", request->dump());
  if (!rep) return unreachable(rep.error());
  if (rep->status != 202) return report_reply(*rep);
  const Json b = Json::parse(rep->body);
  std::cout << b["id"].get<std::string>() << "\n" << std::flush;
  if (a.flag("--wait") || a.opt("--out")) return wait_for(r, b["id"], a.opt("--out"));
  return 0;
}

// The verbs that take a batch id.
int with_id(const std::vector<std::string>& args, const std::string& verb) {
  const CliArgs a = parse_cli(args);
  if (a.words.size() != 1 || (verb == "export" && !a.opt("--out"))) {
    std::cerr << "usage:\n" << kBatchUsage;
    return 2;
  }
  const Remote r = remote(a);
  const std::string id = a.words[0];
  if (verb == "wait") return wait_for(r, id, a.opt("--out"));
  if (verb == "export") return export_to(r, id, *a.opt("--out"));
  auto rep = call(r, verb == "cancel" ? "DELETE" : "GET", "/api/v1/batches/" + id);
  if (!rep) return unreachable(rep.error());
  if (rep->status != 200 && rep->status != 202) return report_reply(*rep);
  std::cout << Json::parse(rep->body).dump(2) << "\n";
  return 0;
}

}  // namespace

SOCSIM_COMMAND("batch submit", kBatchUsage, submit);
SOCSIM_COMMAND("batch status", "", [](const std::vector<std::string>& a) { return with_id(a, "status"); });
SOCSIM_COMMAND("batch wait", "", [](const std::vector<std::string>& a) { return with_id(a, "wait"); });
SOCSIM_COMMAND("batch export", "", [](const std::vector<std::string>& a) { return with_id(a, "export"); });
SOCSIM_COMMAND("batch cancel", "", [](const std::vector<std::string>& a) { return with_id(a, "cancel"); });

}  // namespace socsim::server

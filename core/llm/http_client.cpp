#include "core/llm/http_client.hpp"

#include <curl/curl.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <ctime>
#include <memory>
#include <mutex>

namespace socsim::llm {
namespace {

void global_init() {
  static std::once_flag once;
  std::call_once(once, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
}

struct UrlDeleter {
  void operator()(CURLU* u) const { curl_url_cleanup(u); }
};
struct EasyDeleter {
  void operator()(CURL* c) const { curl_easy_cleanup(c); }
};
struct MultiDeleter {
  void operator()(CURLM* m) const { curl_multi_cleanup(m); }
};
struct ListDeleter {
  void operator()(curl_slist* l) const { curl_slist_free_all(l); }
};

std::optional<std::string> url_part(CURLU* u, CURLUPart part, unsigned flags = 0) {
  char* out = nullptr;
  if (curl_url_get(u, part, &out, flags) != CURLUE_OK || out == nullptr) return std::nullopt;
  std::string s(out);
  curl_free(out);
  return s;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

struct Exchange {
  std::string body;
  std::size_t max_bytes = 0;
  bool too_large = false;
  std::optional<int> retry_after_s;
  const CancelToken* cancel = nullptr;
};

std::size_t on_body(char* data, std::size_t size, std::size_t n, void* user) {
  auto* ex = static_cast<Exchange*>(user);
  const std::size_t bytes = size * n;
  if (ex->body.size() + bytes > ex->max_bytes) {
    ex->too_large = true;
    return 0;  // makes libcurl stop with CURLE_WRITE_ERROR
  }
  ex->body.append(data, bytes);
  return bytes;
}

std::optional<int> parse_retry_after(std::string value) {
  value.erase(0, value.find_first_not_of(" \t"));
  value.erase(value.find_last_not_of(" \t\r\n") + 1);
  if (value.empty()) return std::nullopt;
  if (std::all_of(value.begin(), value.end(), [](unsigned char c) { return std::isdigit(c); })) {
    if (value.size() > 6) return 999999;
    return std::stoi(value);
  }
  const time_t when = curl_getdate(value.c_str(), nullptr);
  if (when < 0) return std::nullopt;
  const time_t now = std::time(nullptr);
  return when > now ? static_cast<int>(std::min<time_t>(when - now, 999999)) : 0;
}

std::size_t on_header(char* data, std::size_t size, std::size_t n, void* user) {
  auto* ex = static_cast<Exchange*>(user);
  const std::size_t bytes = size * n;
  const std::string line(data, bytes);
  if (line.rfind("HTTP/", 0) == 0) {
    ex->retry_after_s.reset();  // a new response (after 100-continue or a redirect) starts
  } else if (const auto colon = line.find(':');
             colon != std::string::npos && lower(line.substr(0, colon)) == "retry-after") {
    ex->retry_after_s = parse_retry_after(line.substr(colon + 1));
  }
  return bytes;
}

int on_progress(void* user, curl_off_t, curl_off_t, curl_off_t, curl_off_t) {
  const auto* ex = static_cast<const Exchange*>(user);
  return ex->cancel->cancelled() ? 1 : 0;  // non-zero aborts with CURLE_ABORTED_BY_CALLBACK
}

TransportFailure classify(CURLcode rc, bool too_large) {
  switch (rc) {
    case CURLE_COULDNT_CONNECT:
    case CURLE_COULDNT_RESOLVE_HOST:
    case CURLE_COULDNT_RESOLVE_PROXY:
    case CURLE_SSL_CONNECT_ERROR:
    case CURLE_PEER_FAILED_VERIFICATION:
    case CURLE_SSL_CACERT_BADFILE:
    case CURLE_SSL_CERTPROBLEM:
    case CURLE_UNSUPPORTED_PROTOCOL:
      return TransportFailure::kConnect;
    case CURLE_OPERATION_TIMEDOUT:
      return TransportFailure::kTimeout;
    case CURLE_PARTIAL_FILE:
    case CURLE_RECV_ERROR:
    case CURLE_SEND_ERROR:
    case CURLE_GOT_NOTHING:
    case CURLE_HTTP2:
    case CURLE_HTTP2_STREAM:
      return TransportFailure::kBroken;
    case CURLE_FILESIZE_EXCEEDED:
      return TransportFailure::kTooLarge;
    case CURLE_WRITE_ERROR:
      return too_large ? TransportFailure::kTooLarge : TransportFailure::kOther;
    case CURLE_ABORTED_BY_CALLBACK:
      return TransportFailure::kCancelled;
    default:
      return TransportFailure::kOther;
  }
}

struct Attempt {
  HttpResponse response;
  std::string redirect_url;  // set for a 3xx with a Location
};

tl::expected<Attempt, TransportError> post_once(const std::string& url, const std::string& body,
                                                curl_slist* headers, const HttpLimits& limits,
                                                const CancelToken& cancel,
                                                std::chrono::steady_clock::time_point deadline) {
  std::unique_ptr<CURL, EasyDeleter> easy(curl_easy_init());
  std::unique_ptr<CURLM, MultiDeleter> multi(curl_multi_init());
  if (!easy || !multi)
    return tl::unexpected(TransportError{TransportFailure::kOther, "libcurl could not be initialised"});

  Exchange ex;
  ex.max_bytes = limits.max_response_bytes;
  ex.cancel = &cancel;
  char errbuf[CURL_ERROR_SIZE] = {0};
  const auto remaining_ms = std::max<long long>(
      1, std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now())
             .count());

  CURL* c = easy.get();
  curl_easy_setopt(c, CURLOPT_URL, url.c_str());
  curl_easy_setopt(c, CURLOPT_PROTOCOLS_STR, "http,https");
  curl_easy_setopt(c, CURLOPT_REDIR_PROTOCOLS_STR, "http,https");
  curl_easy_setopt(c, CURLOPT_FOLLOWLOCATION, 0L);  // redirects are checked and followed below
  curl_easy_setopt(c, CURLOPT_NOSIGNAL, 1L);
  curl_easy_setopt(c, CURLOPT_CONNECTTIMEOUT_MS,
                   static_cast<long>(std::min<long long>(limits.connect_timeout_ms, remaining_ms)));
  curl_easy_setopt(c, CURLOPT_TIMEOUT_MS, static_cast<long>(remaining_ms));
  curl_easy_setopt(c, CURLOPT_LOW_SPEED_LIMIT, 1L);
  curl_easy_setopt(c, CURLOPT_LOW_SPEED_TIME,
                   static_cast<long>(std::max(1, (limits.stall_timeout_ms + 999) / 1000)));
  curl_easy_setopt(c, CURLOPT_MAXFILESIZE_LARGE, static_cast<curl_off_t>(limits.max_response_bytes));
  curl_easy_setopt(c, CURLOPT_ACCEPT_ENCODING, "");
  curl_easy_setopt(c, CURLOPT_USERAGENT, "socsim");
  curl_easy_setopt(c, CURLOPT_HTTPHEADER, headers);
  curl_easy_setopt(c, CURLOPT_POST, 1L);
  curl_easy_setopt(c, CURLOPT_POSTFIELDS, body.data());
  curl_easy_setopt(c, CURLOPT_POSTFIELDSIZE_LARGE, static_cast<curl_off_t>(body.size()));
  curl_easy_setopt(c, CURLOPT_WRITEFUNCTION, &on_body);
  curl_easy_setopt(c, CURLOPT_WRITEDATA, &ex);
  curl_easy_setopt(c, CURLOPT_HEADERFUNCTION, &on_header);
  curl_easy_setopt(c, CURLOPT_HEADERDATA, &ex);
  curl_easy_setopt(c, CURLOPT_NOPROGRESS, 0L);
  curl_easy_setopt(c, CURLOPT_XFERINFOFUNCTION, &on_progress);
  curl_easy_setopt(c, CURLOPT_XFERINFODATA, &ex);
  curl_easy_setopt(c, CURLOPT_ERRORBUFFER, errbuf);

  // The multi interface lets us look at the cancel token every 50 ms even while the server is
  // silent (the progress callback alone may wait up to a second).
  curl_multi_add_handle(multi.get(), c);
  bool cancelled = false;
  int running = 1;
  while (running) {
    if (curl_multi_perform(multi.get(), &running) != CURLM_OK) break;
    if (!running) break;
    if (cancel.cancelled()) {
      cancelled = true;
      break;
    }
    curl_multi_poll(multi.get(), nullptr, 0, 50, nullptr);
  }
  CURLcode rc = CURLE_OK;
  int queued = 0;
  while (CURLMsg* msg = curl_multi_info_read(multi.get(), &queued))
    if (msg->msg == CURLMSG_DONE) rc = msg->data.result;
  curl_multi_remove_handle(multi.get(), c);

  if (cancelled || rc == CURLE_ABORTED_BY_CALLBACK)
    return tl::unexpected(TransportError{TransportFailure::kCancelled, "cancelled"});
  if (rc != CURLE_OK) {
    std::string message = errbuf[0] ? std::string(errbuf) : std::string(curl_easy_strerror(rc));
    const TransportFailure kind = classify(rc, ex.too_large);
    if (kind == TransportFailure::kTooLarge)
      message = "response larger than " + std::to_string(limits.max_response_bytes) + " bytes";
    return tl::unexpected(TransportError{kind, std::move(message)});
  }
  Attempt out;
  curl_easy_getinfo(c, CURLINFO_RESPONSE_CODE, &out.response.status);
  out.response.body = std::move(ex.body);
  out.response.retry_after_s = ex.retry_after_s;
  out.response.effective_url = url;
  if (out.response.status >= 300 && out.response.status < 400) {
    char* location = nullptr;
    if (curl_easy_getinfo(c, CURLINFO_REDIRECT_URL, &location) == CURLE_OK && location)
      out.redirect_url = location;
  }
  return out;
}

}  // namespace

std::string HttpUrl::origin() const {
  const bool default_port = (scheme == "http" && port == 80) || (scheme == "https" && port == 443);
  const bool ipv6 = host.find(':') != std::string::npos && host.front() != '[';
  const std::string h = ipv6 ? "[" + host + "]" : host;
  return scheme + "://" + h + (default_port ? "" : ":" + std::to_string(port));
}

Result<HttpUrl> parse_http_url(std::string_view text) {
  global_init();
  const auto bad = [&](const std::string& why) {
    return fail(ErrorCode::kValidation, "\"" + std::string(text) + "\" " + why);
  };
  std::unique_ptr<CURLU, UrlDeleter> u(curl_url());
  if (!u) return fail(ErrorCode::kInternal, "libcurl could not allocate a URL handle");
  const std::string s(text);
  if (curl_url_set(u.get(), CURLUPART_URL, s.c_str(), 0) != CURLUE_OK)
    return bad("is not an absolute URL (expected http://host[:port][/path] or https://…)");
  HttpUrl url;
  url.scheme = lower(url_part(u.get(), CURLUPART_SCHEME).value_or(""));
  if (url.scheme != "http" && url.scheme != "https") return bad("must use http or https");
  url.host = url_part(u.get(), CURLUPART_HOST).value_or("");
  if (url.host.empty()) return bad("has no host");
  if (url_part(u.get(), CURLUPART_USER) || url_part(u.get(), CURLUPART_PASSWORD))
    return bad("must not contain credentials (use SOCSIM_LLM_API_KEY)");
  if (url_part(u.get(), CURLUPART_QUERY) || url_part(u.get(), CURLUPART_FRAGMENT))
    return bad("must not contain a query or fragment");
  const auto port = url_part(u.get(), CURLUPART_PORT, CURLU_DEFAULT_PORT);
  url.port = port ? std::stoi(*port) : 0;
  url.path = url_part(u.get(), CURLUPART_PATH).value_or("");
  if (url.path == "/") url.path.clear();
  if (url.host.front() == '[' && url.host.back() == ']') url.host = url.host.substr(1, url.host.size() - 2);
  return url;
}

tl::expected<HttpResponse, TransportError> http_post_json(const std::string& url, const std::string& body,
                                                          const std::vector<std::string>& headers,
                                                          const HttpLimits& limits,
                                                          const CancelToken& cancel) {
  global_init();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(limits.timeout_ms);
  std::unique_ptr<curl_slist, ListDeleter> list;
  for (const std::string& h : {std::string("Content-Type: application/json"),
                               std::string("Accept: application/json"), std::string("Expect:")}) {
    list.reset(curl_slist_append(list.release(), h.c_str()));
  }
  for (const auto& h : headers) list.reset(curl_slist_append(list.release(), h.c_str()));

  auto origin = parse_http_url(url);
  if (!origin) return tl::unexpected(TransportError{TransportFailure::kConnect, origin.error().detail});
  std::string current = url;
  for (int hop = 0;; ++hop) {
    auto attempt = post_once(current, body, list.get(), limits, cancel, deadline);
    if (!attempt) return tl::unexpected(attempt.error());
    if (attempt->redirect_url.empty()) return std::move(attempt->response);
    auto target = parse_http_url(attempt->redirect_url);
    if (!target || target->origin() != origin->origin())
      return tl::unexpected(
          TransportError{TransportFailure::kRedirect,
                         "endpoint redirected (HTTP " + std::to_string(attempt->response.status) +
                             ") to another origin, " + attempt->redirect_url + "; not followed"});
    if (hop >= limits.max_redirects)
      return tl::unexpected(TransportError{
          TransportFailure::kRedirect, "more than " + std::to_string(limits.max_redirects) + " redirects"});
    current = attempt->redirect_url;
  }
}

}  // namespace socsim::llm

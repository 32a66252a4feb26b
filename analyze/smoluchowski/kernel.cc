#include "analyze/smoluchowski/kernel.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

namespace {

const char* kAccepted =
    "use constant, additive, product, ballistic (eq4), ballistic2d, ballistic1d or separable:c,p,q[;c,p,q...] "
    "for K = sum c (i^p j^q + i^q j^p) with c > 0";

[[noreturn]] void reject(const std::string& text, const std::string& why) {
  throw InputError("kernel '" + text + "': " + why + "; " + kAccepted);
}

// A number such as 2, -0.5 or a fraction such as -1/6.
double parse_number(const std::string& tok, const std::string& text) {
  auto plain = [&](const std::string& s) {
    double x = 0;
    auto r = std::from_chars(s.data(), s.data() + s.size(), x);
    if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(x))
      reject(text, "'" + tok + "' is not a number");
    return x;
  };
  const auto slash = tok.find('/');
  if (slash == std::string::npos) return plain(tok);
  const double den = plain(tok.substr(slash + 1));
  if (den == 0) reject(text, "'" + tok + "' divides by zero");
  return plain(tok.substr(0, slash)) / den;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(cur);
  if (!s.empty() && s.back() == sep) out.emplace_back();
  return out;
}

std::vector<KernelTerm> parse_separable(const std::string& body, const std::string& text) {
  std::vector<KernelTerm> terms;
  for (const auto& term : split(body, ';')) {
    const auto f = split(term, ',');
    if (f.size() != 3) reject(text, "term '" + term + "' needs three numbers c,p,q");
    KernelTerm t{parse_number(f[0], text), parse_number(f[1], text), parse_number(f[2], text)};
    if (!(t.c > 0)) reject(text, "coefficient " + f[0] + " is not > 0");
    terms.push_back(t);
  }
  if (terms.empty()) reject(text, "no terms");
  return terms;
}

}  // namespace

std::vector<KernelTerm> ballistic_terms(int dimension) {
  switch (dimension) {
    case 1:  // i^-1/2 + j^-1/2
      return {{1, -0.5, 0}};
    case 2:  // (i^-1/2 + j^-1/2)(i^1/2 + j^1/2) = 2 + (i/j)^1/2 + (j/i)^1/2
      return {{1, 0, 0}, {1, 0.5, -0.5}};
    default:
      // (i^-1/2 + j^-1/2)(i^2/3 + 2 i^1/3 j^1/3 + j^2/3) multiplied out: six
      // products, pairing into three symmetric terms.
      return {{1, 1.0 / 6, 0}, {2, -1.0 / 6, 1.0 / 3}, {1, -0.5, 2.0 / 3}};
  }
}

double Kernel::operator()(double i, double j) const {
  double k = 0;
  for (const auto& t : terms) k += t.c * (std::pow(i, t.p) * std::pow(j, t.q) + std::pow(i, t.q) * std::pow(j, t.p));
  return k;
}

std::vector<double> Kernel::exponents() const {
  std::vector<double> e;
  auto add = [&](double x) {
    for (double y : e)
      if (y == x) return;
    e.push_back(x);
  };
  for (const auto& t : terms) {
    add(t.p);
    add(t.q);
  }
  return e;
}

int Kernel::exponent_index(double x) const {
  const auto e = exponents();
  for (std::size_t i = 0; i < e.size(); ++i)
    if (e[i] == x) return static_cast<int>(i);
  return -1;
}

double Kernel::homogeneity() const {
  const double l = terms.front().p + terms.front().q;
  for (const auto& t : terms)
    if (std::abs(t.p + t.q - l) > 1e-12) return std::nan("");
  return l;
}

std::string Kernel::as_separable() const {
  std::string s = "separable:";
  for (std::size_t i = 0; i < terms.size(); ++i) {
    if (i) s += ';';
    s.append(format_number(terms[i].c)).append(",").append(format_number(terms[i].p));
    s.append(",").append(format_number(terms[i].q));
  }
  return s;
}

Kernel parse_kernel(const std::string& text) {
  Kernel k;
  k.text = text;
  if (text == "constant") {
    k.kind = KernelKind::Constant;
    k.terms = {{0.5, 0, 0}};  // ½ (1 + 1)
  } else if (text == "additive") {
    k.kind = KernelKind::Additive;
    k.terms = {{1, 1, 0}};  // i + j
  } else if (text == "product") {
    k.kind = KernelKind::Product;
    k.terms = {{0.5, 1, 1}};  // ½ (ij + ij)
  } else if (text == "ballistic" || text == "eq4" || text == "ballistic2d" || text == "ballistic1d") {
    k.kind = KernelKind::Ballistic;
    k.terms = ballistic_terms(text == "ballistic2d" ? 2 : text == "ballistic1d" ? 1 : 3);
  } else if (text.rfind("separable:", 0) == 0) {
    k.terms = parse_separable(text.substr(10), text);
  } else {
    reject(text, "unknown kernel");
  }
  return k;
}

}  // namespace coolgas::smoluchowski

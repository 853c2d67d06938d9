// QuasiDynamic: rate-and-state faults integrated on the fault alone (QuasiDynamic.hpp).
#include "friction/time/QuasiDynamic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "friction/control/Complementarity.hpp"
#include "friction/control/SlipResponse.hpp"
#include "friction/core/InputError.hpp"
#include "friction/core/StopRequest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/DictionaryWriter.hpp"
#include "friction/law/RateState.hpp"
#include "friction/linalg/DenseProduct.hpp"
#include "friction/output/FaultSeries.hpp"

namespace friction {

QuasiDynamic::QuasiDynamic(const Dictionary* d) {
  if (!d) return;
  relTol_ = d->getScalarOr("relativeTolerance", relTol_, Bounds{1e-14, 1e-1});
  absSlip_ = d->getScalarOr("absoluteSlipTolerance", absSlip_, Bounds::positive());
  absState_ = d->getScalarOr("absoluteStateTolerance", absState_, Bounds::positive());
  maxStep_ = d->getScalarOr("maxStep", 0.0, Bounds::nonNegative());
  scheme_ = d->getChoiceOr("scheme", {"dormandPrince54", "bogackiShampine32"}, "dormandPrince54") ==
                    "dormandPrince54"
                ? RungeKuttaScheme::dormandPrince54
                : RungeKuttaScheme::bogackiShampine32;
  // faultOperator: a word, or a sub-dictionary with its type and the compression's settings.
  const std::vector<std::string> operators = {"auto", "dense", "hierarchical"};
  std::string type = "auto", precision = "auto";
  if (d->isDict("faultOperator")) {
    const Dictionary& f = d->subDict("faultOperator");
    type = f.getChoice("type", operators);
    if (type == "hierarchical" && f.found("precision"))
      throw InputError(f.location("precision"),
                       "'precision' applies to a dense S (type dense or auto): the H-matrix's "
                       "blocks are kept in double");
    if (type != "hierarchical")
      precision = f.getChoiceOr("precision", {"auto", "double", "single"}, "auto");
    if (type != "dense") {
      hSettings_.tolerance = f.getScalarOr("tolerance", hSettings_.tolerance, Bounds{1e-14, 1e-1});
      hSettings_.eta = f.getScalarOr("eta", hSettings_.eta, Bounds{0.1, 100});
      hSettings_.leafSize =
          static_cast<int>(f.getIntOr("leafSize", hSettings_.leafSize, Bounds{4, 4096}));
    }
    f.checkAllRead();
  } else {
    type = d->getChoiceOr("faultOperator", operators, "auto");
  }
  choice_ = type == "auto"    ? OperatorChoice::automatic
            : type == "dense" ? OperatorChoice::dense
                              : OperatorChoice::hierarchical;
  hierarchical_ = choice_ == OperatorChoice::hierarchical;
  precision_ = precision == "auto"     ? Precision::automatic
               : precision == "double" ? Precision::full
                                       : Precision::single;
}

std::string QuasiDynamic::describe() const {
  std::ostringstream s;
  s << (scheme_ == RungeKuttaScheme::dormandPrince54 ? "Dormand-Prince 5(4)"
                                                     : "Bogacki-Shampine 3(2)")
    << ", relativeTolerance " << relTol_ << ", absoluteSlipTolerance " << absSlip_
    << " m, absoluteStateTolerance " << absState_;
  if (maxStep_ > 0) s << ", maxStep " << maxStep_ << " s";
  if (precision_ == Precision::single)
    s << "; a dense S of the right-hand side stored in single precision";
  else if (precision_ == Precision::automatic && choice_ != OperatorChoice::hierarchical)
    s << "; a dense S of the right-hand side stored in single precision where it has "
      << autoSingleFrom << " entries or more";
  if (choice_ != OperatorChoice::dense)
    s << "; S of the right-hand side as an H-matrix"
      << (choice_ == OperatorChoice::automatic
              ? " where S_tt has " + std::to_string(autoHierarchicalFrom) + " rows or more"
              : std::string())
      << " (tolerance " << hSettings_.tolerance << ", eta " << hSettings_.eta << ", leafSize "
      << hSettings_.leafSize << ")";
  return s.str();
}

std::string QuasiDynamic::prepare(StepHost& host) {
  // The tractions come from S: the condensed Newton's operator, formed once per run.
  std::string built = host.prepareSolver();
  const RateStateFault fault = host.rateStateFault();
  const Eigen::Index n = fault.positions.cols(), k = fault.k;
  const InterfaceOperator& S = host.faultOperator();
  // The moved nodes, and S on them where some node is not moved.
  solved_.clear();
  solvedIndex_.assign(static_cast<std::size_t>(n), -1);
  for (Eigen::Index i = 0; i < n; ++i)
    if (fault.componentMask.segment(k * i, k).any() && (*fault.imposed)[i] == 0) {
      solvedIndex_[static_cast<std::size_t>(i)] = static_cast<Eigen::Index>(solved_.size());
      solved_.push_back(i);
    }
  const Eigen::Index ns = static_cast<Eigen::Index>(solved_.size());
  reduced_ = ns < n;
  Ssolved_.resize(0, 0);
  if (reduced_) {
    Ssolved_.resize((k + 1) * ns, k * ns);
    for (Eigen::Index b = 0; b < ns; ++b)
      for (Eigen::Index cb = 0; cb < k; ++cb) {
        const Eigen::Index col = k * solved_[static_cast<std::size_t>(b)] + cb;
        for (Eigen::Index a = 0; a < ns; ++a) {
          const Eigen::Index i = solved_[static_cast<std::size_t>(a)];
          for (Eigen::Index ca = 0; ca < k; ++ca)
            Ssolved_(k * a + ca, k * b + cb) = S.Stt(k * i + ca, col);
          Ssolved_(k * ns + a, k * b + cb) = S.Snt(i, col);
        }
      }
    std::ostringstream s;
    s << (built.empty() ? std::string() : built + "; ") << "S of the right-hand side on the " << ns
      << " nodes that rate-and-state moves, of " << n << " (" << n - ns
      << " creeping or held: their slip is given, their load one product per interval)";
    built = s.str();
  }
  const Eigen::Index kn = k * ns;  // the right-hand side's S_tt: kn × kn
  // What the dense products run on (DenseProduct.hpp): the kernel and its threads.
  const std::string denseKernel =
      " (dense products: " + describeDenseProduct(static_cast<long>((k + 1) * ns * kn)) + ")";
  if (choice_ == OperatorChoice::automatic) {
    hierarchical_ = kn >= autoHierarchicalFrom;
    if (!hierarchical_)
      return (built.empty() ? std::string() : built + "; ") +
             "S of the right-hand side dense (faultOperator auto: S_tt " + std::to_string(kn) +
             " x " + std::to_string(kn) + ", below " + std::to_string(autoHierarchicalFrom) +
             " rows)" + storeDense(S) + denseKernel;
  }
  if (!hierarchical_)
    return (built.empty() ? std::string("S of the right-hand side dense") : built) + storeDense(S) +
           denseKernel;
  // Compressed once per run: rows [τ (k·ns); σ_n (ns)] and columns (k·ns) belong to the moved
  // nodes (all of them unless reduced_).
  std::vector<Eigen::Index> rowPoint(static_cast<std::size_t>(kn + ns)),
      colPoint(static_cast<std::size_t>(kn));
  const auto node = [&](Eigen::Index a) {
    return reduced_ ? solved_[static_cast<std::size_t>(a)] : a;
  };
  for (Eigen::Index r = 0; r < kn; ++r) rowPoint[static_cast<std::size_t>(r)] = node(r / k);
  for (Eigen::Index a = 0; a < ns; ++a) rowPoint[static_cast<std::size_t>(kn + a)] = node(a);
  for (Eigen::Index c = 0; c < kn; ++c) colPoint[static_cast<std::size_t>(c)] = node(c / k);
  const auto source = [&](const std::vector<Eigen::Index>& rows,
                          const std::vector<Eigen::Index>& cols, Eigen::MatrixXd& out) {
    for (std::size_t a = 0; a < rows.size(); ++a) {
      const Eigen::Index r = rows[a];
      for (std::size_t b = 0; b < cols.size(); ++b)
        out(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) =
            reduced_ ? Ssolved_(r, cols[b])
            : r < kn ? S.Stt(r, cols[b])
                     : S.Snt(r - kn, cols[b]);
    }
  };
  H_ =
      std::make_unique<HierarchicalMatrix>(source, fault.positions, rowPoint, colPoint, hSettings_);
  // auto keeps the H-matrix only where it stores at most autoHierarchicalShare of S's entries:
  // a deterministic rule (a restart decides alike), where a timing would not be. On a fault
  // surface of a few thousand nodes most blocks are near each other and stay dense.
  const double share = H_->stats().storedEntries / H_->stats().denseEntries;
  if (choice_ == OperatorChoice::automatic && share > autoHierarchicalShare) {
    std::ostringstream s;
    s << (built.empty() ? std::string() : built + "; ")
      << "S of the right-hand side dense (faultOperator auto: S_tt " << kn << " rows; an H-matrix "
      << "would store " << std::fixed << std::setprecision(1) << 100 * share
      << " % of its entries, more than " << 100 * autoHierarchicalShare << " %)";
    H_.reset();
    hierarchical_ = false;
    s << storeDense(S) << denseKernel;
    return s.str();
  }
  // What a product costs either way, measured here in one run (alternating, the best of
  // several: this machine is shared), and how far apart the two are on a slip of every node.
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(kn, -1.0, 1.0).array().sin();
  for (Eigen::Index c = 0; c < kn; ++c) x[c] *= fault.componentMask[k * node(c / k) + c % k];
  Eigen::VectorXd yH, yT, yN, yD;
  double denseBest = 1e300, hBest = 1e300;
  for (int rep = 0; rep < 5; ++rep) {
    const auto c0 = std::chrono::steady_clock::now();
    if (reduced_) {
      denseProduct(Ssolved_, x, yD);
    } else {
      denseProduct(S.Stt, x, yT);
      denseProduct(S.Snt, x, yN);
      yD.resize(kn + ns);
      yD << yT, yN;
    }
    const auto c1 = std::chrono::steady_clock::now();
    H_->multiply(x, yH);
    const auto c2 = std::chrono::steady_clock::now();
    denseBest = std::min(denseBest, std::chrono::duration<double>(c1 - c0).count());
    hBest = std::min(hBest, std::chrono::duration<double>(c2 - c1).count());
  }
  std::ostringstream s;
  s << (built.empty() ? std::string() : built + "; ") << "S_tt and S_nt of the right-hand side "
    << (choice_ == OperatorChoice::automatic
            ? "(faultOperator auto: S_tt " + std::to_string(kn) + " rows, from " +
                  std::to_string(autoHierarchicalFrom) + ") "
            : std::string())
    << H_->stats().describe(static_cast<long>(kn + ns), static_cast<long>(kn)) << "; a product "
    << std::setprecision(3) << 1e6 * hBest << " us against the dense S's " << 1e6 * denseBest
    << " us (" << denseBest / std::max(hBest, 1e-12) << "x), relative difference "
    << (yD.norm() > 0 ? (yH - yD).norm() / yD.norm() : 0.0);
  Ssolved_.resize(0, 0);  // the H-matrix holds it now
  return s.str();
}

std::string QuasiDynamic::storeDense(const InterfaceOperator& S) {
  const Eigen::Index ns = static_cast<Eigen::Index>(solved_.size());
  const Eigen::Index k = S.Stt.rows() / std::max<Eigen::Index>(S.Snt.rows(), 1);
  const long entries = static_cast<long>((k + 1) * ns) * static_cast<long>(k * ns);
  single_ = precision_ == Precision::single ||
            (precision_ == Precision::automatic && entries >= autoSingleFrom);
  Ssingle_.resize(0, 0);
  if (!single_) return std::string();
  // [S_tt; S_nt] on the moved nodes, rounded to float once; the double copy of the reduced S
  // is let go (the case's own S stays: the outputs' rows and the creep's columns read it).
  if (reduced_) {
    Ssingle_ = Ssolved_.cast<float>();
    Ssolved_.resize(0, 0);
  } else {
    Ssingle_.resize(S.Stt.rows() + S.Snt.rows(), S.Stt.cols());
    Ssingle_.topRows(S.Stt.rows()) = S.Stt.cast<float>();
    Ssingle_.bottomRows(S.Snt.rows()) = S.Snt.cast<float>();
  }
  std::ostringstream s;
  s << std::setprecision(3) << ", stored in single precision ("
    << (precision_ == Precision::automatic
            ? "faultOperator's precision auto: " + std::to_string(entries) + " entries, from " +
                  std::to_string(autoSingleFrom) + "; "
            : std::string())
    << static_cast<double>(Ssingle_.size()) * sizeof(float) / 1e6
    << " MB; each entry within 6e-8 of the double one, the sums in double)";
  return s.str();
}

Eigen::VectorXd QuasiDynamic::creepResponse(const InterfaceOperator& S,
                                            const RateStateFault& f) const {
  const Eigen::Index n = f.positions.cols(), k = f.k;
  const Eigen::Index ns = static_cast<Eigen::Index>(solved_.size());
  Eigen::VectorXd w = Eigen::VectorXd::Zero((k + 1) * ns);
  for (Eigen::Index j = 0; j < n; ++j) {
    if (solvedIndex_[static_cast<std::size_t>(j)] >= 0) continue;
    for (Eigen::Index c = 0; c < k; ++c) {
      const Eigen::Index col = k * j + c;
      const double v = (*f.imposed)[j] != 0 ? (*f.imposedRate)[col] * f.componentMask[col] : 0.0;
      if (v == 0) continue;
      for (Eigen::Index a = 0; a < ns; ++a) {
        const Eigen::Index i = solved_[static_cast<std::size_t>(a)];
        for (Eigen::Index ca = 0; ca < k; ++ca) w[k * a + ca] += S.Stt(k * i + ca, col) * v;
        w[k * ns + a] += S.Snt(i, col) * v;
      }
    }
  }
  return w;
}

void QuasiDynamic::advance(StepHost& host, StepResult& r, const StepResult* /*previous*/) {
  const double tA = host.stateTime(), tB = r.time;
  const StepLoads loadsA = host.loadsAt(tA);
  Eigen::VectorXd tauA, sigmaA, tauB, sigmaB;
  host.tractionsAt(loadsA, tA, tauA, sigmaA);
  const StepLoads loadsB = host.loadsAt(tB);
  host.tractionsAt(loadsB, tB, tauB, sigmaB);
  const InterfaceOperator& S = host.faultOperator();
  RateStateFault fault = host.rateStateFault();
  const int k = fault.k;
  const Eigen::Index n = fault.psi->size(), kn = k * n;
  const Eigen::VectorXd sA = *fault.slip;
  const Eigen::VectorXd& mask = fault.componentMask;
  std::vector<RateState> laws = *fault.laws;
  const double span = tB - tA;
  // Reduced to the moved nodes: the creeping nodes' load grows at the rate creep, and a moved
  // node's slip increment is read from and its tractions written to the whole vectors.
  const Eigen::Index ns = static_cast<Eigen::Index>(solved_.size());
  const Eigen::VectorXd creep = reduced_ ? creepResponse(S, fault) : Eigen::VectorXd();
  // The tractions caused by a slip increment ds at time t: S_tt ds and S_nt ds, dense or
  // compressed; reduced, on the moved nodes' rows only (0 elsewhere), with the creeping
  // nodes' increment (t − tA)·rate (the rate is constant, so that is exactly what the
  // Runge–Kutta stages integrate to).
  const auto elasticIncrement = [&](const Eigen::VectorXd& ds, double t, Eigen::VectorXd& dtau,
                                    Eigen::VectorXd& dsigma) {
    if (reduced_) {
      Eigen::VectorXd x(k * ns), y;
      for (Eigen::Index a = 0; a < ns; ++a)
        x.segment(k * a, k) = ds.segment(k * solved_[static_cast<std::size_t>(a)], k);
      if (H_)
        H_->multiply(x, y);
      else if (single_)
        denseProduct(Ssingle_, x, y);
      else
        denseProduct(Ssolved_, x, y);
      y += (t - tA) * creep;
      dtau.setZero(kn);
      dsigma.setZero(n);
      for (Eigen::Index a = 0; a < ns; ++a) {
        const Eigen::Index i = solved_[static_cast<std::size_t>(a)];
        dtau.segment(k * i, k) = y.segment(k * a, k);
        dsigma[i] = y[k * ns + a];
      }
    } else if (H_ || single_) {
      Eigen::VectorXd y;
      if (H_)
        H_->multiply(ds, y);
      else
        denseProduct(Ssingle_, ds, y);
      dtau = y.head(kn);
      dsigma = y.tail(n);
    } else {
      denseProduct(S.Stt, ds, dtau);
      denseProduct(S.Snt, ds, dsigma);
    }
  };

  // The last right-hand side's elastic increment, kept for the fault outputs: the embedded
  // Runge–Kutta pairs evaluate at each accepted step's end (first same as last), where the
  // outputs sample, so the sample needs no product of its own.
  struct LastIncrement {
    double t = std::numeric_limits<double>::quiet_NaN();
    Eigen::VectorXd s, dtau, dsigma;
  } last;
  // The slip rate of every free component at (t, s, ψ), into V (k·n); false where a node's
  // balance has no solution (σ̄ ≤ 0: the fault opens; a law's solve failed).
  const auto slipRates = [&](double t, const Eigen::VectorXd& s, const Eigen::VectorXd& psi,
                             Eigen::VectorXd& V) {
    const double theta = span > 0 ? (t - tA) / span : 1.0;
    const Eigen::VectorXd ds = (s - sA).cwiseProduct(mask);
    Eigen::VectorXd tau, sigma;
    elasticIncrement(ds, t, tau, sigma);
    last.t = t;
    last.s = s;
    last.dtau = tau;
    last.dsigma = sigma;
    tau += tauA + theta * (tauB - tauA);
    sigma += sigmaA + theta * (sigmaB - sigmaA);
    const Eigen::VectorXd p = loadsA.pressure + theta * (loadsB.pressure - loadsA.pressure);
    V.setZero(kn);
    for (Eigen::Index i = 0; i < n; ++i) {
      bool free = false;
      for (int c = 0; c < k; ++c) free |= mask[k * i + c] != 0;
      if (!free) continue;
      if ((*fault.imposed)[i] != 0) {  // creep: the rate is given
        for (int c = 0; c < k; ++c)
          V[k * i + c] = (*fault.imposedRate)[k * i + c] * mask[k * i + c];
        continue;
      }
      RateState& law = laws[static_cast<std::size_t>(i)];
      law.sigmaBar = -(sigma[i] + p[i]);
      if (!(law.sigmaBar > 0)) return false;
      // φ = −τ on the free components; V along φ.
      Block phi(k);
      for (int c = 0; c < k; ++c) phi[c] = -tau[k * i + c] * mask[k * i + c];
      const double phiNorm = blockNorm(phi);
      if (phiNorm == 0) continue;
      const SlipRate v = law.slipRate(phiNorm, psi[i]);
      if (!v.converged()) return false;
      for (int c = 0; c < k; ++c) V[k * i + c] = v.V * phi[c] / phiNorm;
    }
    return true;
  };
  const RightHandSide rhs = [&](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    // A second SIGINT/SIGTERM abandons the step here, as between two solves of the
    // quasi-static stepping (an interval may take many steps).
    throwIfStopNow();
    const Eigen::VectorXd s = y.head(kn), psi = y.tail(n);
    Eigen::VectorXd V;
    if (!slipRates(t, s, psi, V)) return false;
    dydt.resize(kn + n);
    dydt.head(kn) = V;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double speed = blockNorm(V.segment(k * i, k));
      dydt[kn + i] = mask.segment(k * i, k).any() && (*fault.imposed)[i] == 0
                         ? laws[static_cast<std::size_t>(i)].stateRate(speed, psi[i])
                         : 0.0;
    }
    return true;
  };

  RungeKuttaSettings settings;
  settings.scheme = scheme_;
  settings.relTol = Eigen::VectorXd::Constant(1, relTol_);
  settings.absTol.resize(kn + n);
  settings.absTol.head(kn).setConstant(absSlip_);
  settings.absTol.tail(n).setConstant(absState_);
  settings.initialStep = nextStep_;
  if (maxStep_ > 0) settings.maxStep = maxStep_;
  EmbeddedRungeKutta rk(rhs, settings);
  Eigen::VectorXd y(kn + n);
  y.head(kn) = sA;
  y.tail(n) = *fault.psi;
  // The case's fault outputs sample the state at the interval's start and at every accepted
  // step: the tractions there by rows of S, on demand.
  const bool sampling = host.wantsRateSamples();
  const auto sample = [&](double t, const Eigen::VectorXd& s, const Eigen::VectorXd& psi,
                          const Eigen::VectorXd& V) {
    const double theta = span > 0 ? (t - tA) / span : 1.0;
    const Eigen::VectorXd ds = (s - sA).cwiseProduct(mask);
    RateSample smp;
    smp.time = t;
    smp.slip = &s;
    smp.psi = &psi;
    smp.rate = &V;
    // Compressed or reduced: the whole product once, on the first moved node asked for (the
    // tractions the integration used: compressed, they differ from the dense S's by the
    // compression's error). Other nodes, and every node with the whole dense S: rows of S.
    Eigen::VectorXd dtau, dsigma;
    smp.traction = [&](Eigen::Index i, Eigen::VectorXd& tau, double& sigmaEff) {
      const bool product = (H_ || reduced_ || single_) &&
                           (!reduced_ || solvedIndex_[static_cast<std::size_t>(i)] >= 0);
      if (product && dtau.size() == 0) {
        if (last.t == t && last.s.size() == s.size() && last.s == s) {
          dtau = last.dtau;  // the same product, made by the step's last stage
          dsigma = last.dsigma;
        } else {
          elasticIncrement(ds, t, dtau, dsigma);
        }
      }
      tau.resize(k);
      for (int c = 0; c < k; ++c) {
        const Eigen::Index row = k * i + c;
        tau[c] = tauA[row] + theta * (tauB[row] - tauA[row]) +
                 (product ? dtau[row] : S.Stt.row(row).dot(ds));
      }
      sigmaEff = sigmaA[i] + theta * (sigmaB[i] - sigmaA[i]) +
                 (product ? dsigma[i] : S.Snt.row(i).dot(ds)) + loadsA.pressure[i] +
                 theta * (loadsB.pressure[i] - loadsA.pressure[i]);
    };
    host.rateSample(smp);
  };
  if (sampling) {
    Eigen::VectorXd V0;
    if (slipRates(tA, sA, *fault.psi, V0)) sample(tA, sA, *fault.psi, V0);
  }
  // The largest slip rate over the interval's accepted steps (an event between two written
  // times shows there): the derivative at each step's end holds the slip rates.
  double peak = 0;
  const StepObserver observer = [&](const AcceptedStep& step) {
    for (Eigen::Index i = 0; i < n; ++i)
      peak = std::max(peak, blockNorm(step.dydt1.segment(k * i, k)));
    if (sampling) {
      const Eigen::VectorXd s = step.y1.head(kn), psi = step.y1.tail(n), V = step.dydt1.head(kn);
      sample(step.t1, s, psi, V);
    }
    return true;
  };
  const auto clock0 = std::chrono::steady_clock::now();
  const IntegrationReport report = rk.integrate(tA, tB, y, observer);
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();
  faultUnknowns_ = k * ns;
  accepted_ += report.work.acceptedSteps;
  rejected_ += report.work.rejectedSteps;
  evaluations_ += report.work.evaluations;
  r.report.iterations = static_cast<int>(report.work.acceptedSteps);
  if (!report.ok()) {
    std::ostringstream note;
    note << "the time integration stopped at t = " << report.t << " s ("
         << (report.status == IntegrationStatus::stepTooSmall ? "step too small"
             : report.status == IntegrationStatus::initialEvaluationFailed
                 ? "no slip rate at the start: a node's normal stress is not compressive, or its "
                   "law has no solution"
                 : "too many steps")
         << "); the state written is the one reached";
    r.report.status = OptimizerStatus::diverged;
    r.report.note = note.str();
  } else {
    r.report.status = OptimizerStatus::converged;
    nextStep_ = report.nextStep;
  }
  *fault.psi = y.tail(n);
  Eigen::VectorXd V;
  if (!slipRates(report.t, y.head(kn), y.tail(n), V)) V = Eigen::VectorXd::Zero(kn);
  double vmax = 0;
  for (Eigen::Index i = 0; i < n; ++i) vmax = std::max(vmax, blockNorm(V.segment(k * i, k)));
  r.maxSlipRate = vmax;
  r.peakSlipRate = std::max(peak, vmax);
  host.finishRateStep(loadsB, tB, y.head(kn), V, r);
  if (!report.ok()) r.report.status = OptimizerStatus::diverged;
}

std::string QuasiDynamic::summary() const {
  std::ostringstream s;
  s << accepted_ << " Runge-Kutta steps accepted, " << rejected_ << " rejected, " << evaluations_
    << " right-hand sides in " << std::setprecision(4) << seconds_ << " s";
  if (evaluations_ > 0)
    s << " (" << 1e6 * seconds_ / static_cast<double>(evaluations_)
      << " us each, fault outputs included; S_tt " << faultUnknowns_ << " x " << faultUnknowns_
      << ")";
  return s.str();
}

double QuasiDynamic::balanceTolerance(double controlTolerance) const {
  // The integration's tractions are S's product; the written state's come from a solve of the
  // body. With S compressed they differ by the compression's error (block by block within
  // its tolerance), so the balance cannot be judged tighter than that.
  if (hierarchical_) return std::max(controlTolerance, hSettings_.tolerance);
  return single_ ? std::max(controlTolerance, singleBalanceTolerance) : controlTolerance;
}

std::string QuasiDynamic::balanceNote() const {
  std::ostringstream s;
  s << std::setprecision(3);
  if (hierarchical_)
    s << "the integration's tractions came from S compressed to an H-matrix within "
      << hSettings_.tolerance
      << " block by block, the written state's from a solve of the body: they differ by more "
         "than the bound; tighten faultOperator's tolerance or use faultOperator dense";
  else if (single_)
    s << "the integration's tractions came from S stored in single precision, the written "
         "state's from a solve of the body: they differ by more than the bound "
      << singleBalanceTolerance << "; set faultOperator { type dense; precision double; }";
  else
    s << "the integration's tractions came from S, the written state's from a solve of the "
         "body: they differ by more than round-off; tighten the control's tolerance only if "
         "this recurs (an ill-conditioned S)";
  return s.str();
}

void QuasiDynamic::writeState(DictionaryWriter& out) const { out.entry("nextStep", nextStep_); }

void QuasiDynamic::readState(const Dictionary& in) {
  nextStep_ = in.getScalar("nextStep", Bounds::nonNegative());
}

}  // namespace friction

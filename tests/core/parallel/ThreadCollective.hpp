// dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
// Tests: ranks simulated by threads of one process, for the core's divided
// algorithms without MPI. runRanks(P, f) runs f(collective) on P threads,
// each with its own ThreadCollective over one shared exchange; every
// operation is a write to the rank's slot, a barrier, a read of all slots
// and a second barrier (so a fast rank cannot overwrite a slot still read).
// Where MPI would hang, a test fails instead: a rank that throws, or that
// ends while another still waits in (or later enters) a collective call,
// makes the waiting ranks throw RankFailure.
#pragma once

#include "Collective.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace dcprbf
{
namespace test
{

//- A collective call that cannot complete (another rank threw or ended)
struct RankFailure : std::runtime_error
{
    RankFailure()
    :
        std::runtime_error("a collective call left waiting: another rank failed or ended")
    {}
};


class ThreadCollective final : public Collective
{
public:
    //- What the ranks share
    struct Exchange
    {
        explicit Exchange(int n) : size(n), slots(n) {}

        void barrier()
        {
            std::unique_lock<std::mutex> lock(mutex);
            if (ended) throw RankFailure();
            const long generation = passed;
            if (++waiting == size)
            {
                waiting = 0;
                ++passed;
                wake.notify_all();
            }
            else
            {
                wake.wait(lock, [&] { return passed != generation || ended; });
                if (passed == generation) throw RankFailure();
            }
        }

        //- A rank is done (returned or threw): no collective can complete
        void end()
        {
            std::lock_guard<std::mutex> lock(mutex);
            ended = true;
            wake.notify_all();
        }

        const int size;
        std::vector<std::vector<double>> slots;
        std::mutex mutex;
        std::condition_variable wake;
        int waiting = 0;
        long passed = 0;
        bool ended = false;
    };

    ThreadCollective(Exchange& exchange, int rank)
    :
        exchange_(exchange),
        rank_(rank)
    {}

    using Collective::max;

    int size() const override { return exchange_.size; }
    int rank() const override { return rank_; }

    void max(double* v, Eigen::Index n) const override
    {
        const std::vector<std::vector<double>>& all = share(v, n);
        for (Eigen::Index k = 0; k < n; ++k)
        {
            for (const std::vector<double>& s : all) v[k] = std::max(v[k], s[k]);
        }
        exchange_.barrier();
    }

    void broadcast(double* v, Eigen::Index n, int root) const override
    {
        const std::vector<std::vector<double>>& all = share(v, n);
        std::copy(all[root].begin(), all[root].end(), v);
        exchange_.barrier();
    }

    std::vector<Eigen::Index> allGather(Eigen::Index value) const override
    {
        const double v = double(value);
        const std::vector<std::vector<double>>& all = share(&v, 1);
        std::vector<Eigen::Index> values;
        for (const std::vector<double>& s : all) values.push_back(Eigen::Index(s[0]));
        exchange_.barrier();
        return values;
    }

private:
    //- Every rank's v, after the first barrier
    const std::vector<std::vector<double>>& share(const double* v, Eigen::Index n) const
    {
        exchange_.slots[rank_].assign(v, v + n);
        exchange_.barrier();
        return exchange_.slots;
    }

    Exchange& exchange_;
    const int rank_;
};


//- f(collective) on P threads standing for ranks; rethrows the first
//  rank's exception (after every rank has ended): a rank's own exception
//  before another's RankFailure
inline void runRanks(int P, const std::function<void(const Collective&)>& f)
{
    ThreadCollective::Exchange exchange(P);
    std::vector<std::exception_ptr> failed(P);
    std::vector<std::thread> ranks;
    for (int r = 0; r < P; ++r)
    {
        ranks.emplace_back([&, r]
        {
            try
            {
                f(ThreadCollective(exchange, r));
            }
            catch (...)
            {
                failed[r] = std::current_exception();
            }
            exchange.end();
        });
    }
    for (std::thread& t : ranks) t.join();
    for (bool own : {true, false})
    {
        for (const std::exception_ptr& e : failed)
        {
            if (!e) continue;
            try
            {
                std::rethrow_exception(e);
            }
            catch (const RankFailure&)
            {
                if (!own) throw;
            }
            catch (...)
            {
                if (own) throw;
            }
        }
    }
}

} // namespace test
} // namespace dcprbf

#include "map/MergeCascade.h"

#include <algorithm>

namespace gridvector
{
// Algorithm 2, repeated while the merged vector finds correspondents (Sec. 3.2).
MergeCascadeStats mergeCascade(const VectorMerger& merger, GridVector& v, const MergePool& pool, int maxMerges)
{
	MergeCascadeStats st;
	std::vector<uint64_t> refused;  // keys whose merge the guard refused
	for (int round = 0; round < maxMerges; ++round)
	{
		std::vector<MergeCandidate> corr = pool.correspondents(v);
		corr.erase(std::remove_if(corr.begin(), corr.end(),
								  [&](const MergeCandidate& c) {
									  return std::find(refused.begin(), refused.end(), c.key) != refused.end();
								  }),
				   corr.end());
		if (corr.empty()) break;
		std::vector<const GridVector*> cand;
		for (const MergeCandidate& c : corr) cand.push_back(c.vector);
		GridVector merged;
		const std::vector<size_t> taken = merger.mergeGreedy(v, cand, merged);
		std::vector<MergeCandidate> absorbed;
		for (size_t k = 0, j = 0; k < corr.size(); ++k)
			if (j < taken.size() && taken[j] == k)
				absorbed.push_back(corr[k]), ++j;
			else
				refused.push_back(corr[k].key);
		st.refused += corr.size() - absorbed.size();
		if (absorbed.empty()) break;
		++st.merges;
		st.absorbed += absorbed.size();
		pool.absorb(absorbed);
		v = std::move(merged);
	}
	return st;
}

}  // namespace gridvector

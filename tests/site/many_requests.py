"""N requests for one page at once (scripts/site --serve in the deep checks): each must
come back whole. Usage: many_requests.py URL N"""

import concurrent.futures
import sys
import urllib.request


def main(url, count):
    expected = urllib.request.urlopen(url, timeout=30).read()
    with concurrent.futures.ThreadPoolExecutor(count) as pool:
        pages = list(
            pool.map(lambda _: urllib.request.urlopen(url, timeout=60).read(), range(count))
        )
    same = sum(page == expected for page in pages)
    print(f"{count} requests at once: {same} had the page")
    return 0 if same == count else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2])))

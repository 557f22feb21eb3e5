CDF not really
